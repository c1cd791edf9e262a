/*
 * tetrahedralize.c — lh_tetrahedralize, the pipeline (docs/meshing3d.md): check the
 * PLC and that its facets do not intersect; the Delaunay tetrahedralization of its
 * points; facets triangulated in their
 * planes; boundary recovery (recover.h); carving and regions (carve.c); the mesh.
 */
#include "carve.h"
#include "facets.h"
#include "refine.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static void ctx_free(t3_ctx *c)
{
    void *arrays[] = {c->xyz,      c->tri,         c->tri_facet, c->tri_seg,     c->seg,
                      c->seg_key,  c->patch_first, c->patch_tri, c->patch_facet, c->patch_axis,
                      c->pnode,    c->pnode_first, c->node,      c->node_first,  c->new_xyz,
                      c->new_node, c->star_first,  c->star,      c->stamp,       c->vbuf,
                      c->fbuf,     c->ebuf,        c->changed,   c->seg_seen,    c->patch_seen,
                      c->cover,    c->cover_first, c->cover_len, c->tv,          c->tn,
                      c->vtet,     c->tmark,       c->sbuf,      c->lock,        c->lock_first,
                      c->jbuf,     c->todo,        c->seg_order, c->patch_order,
                      c->pmark,    c->xlock,       c->sides,     c->rbuf,        c->left};
    for (size_t i = 0; i < sizeof arrays / sizeof arrays[0]; i++) lh__free(&c->al, arrays[i]);
    lh_tri_free(c->dt);
    lh_pred_free(c->pred);
}

/* The Delaunay tetrahedralization of the PLC's points, and c's copy of them. */
static lh_status start(t3_ctx *c)
{
    const lh_plc *g = c->g;
    lh_options dopt;
    lh_options_default(&dopt);
    dopt.alloc = c->opt->alloc;
    dopt.threads = c->opt->threads;
    lh_status st = lh_pred_create(c->opt->alloc, &c->pred);
    if (st != LH_OK) return lh__t3_say(c, st, 0, "out of memory");
    st = lh_delaunay(3, g->n, g->xyz, &dopt, &c->dt);
    if (st == LH_ERR_DEGENERATE)
        return lh__t3_say(c, st, 0,
                          "the points are coplanar, or fewer than 4 distinct: no volume to mesh");
    if (st != LH_OK) return lh__t3_say(c, st, 0, "%s", lh_status_message(st));
    c->dup = lh_tri_duplicate_of(c->dt);
    c->n = c->n_input = g->n;
    c->n_cap = 2 * g->n + 16;
    c->xyz = lh__alloc(&c->al, 3 * c->n_cap * sizeof(double));
    if (!c->xyz) return lh__t3_say(c, LH_ERR_NOMEM, 0, "out of memory");
    memcpy(c->xyz, g->xyz, 3 * g->n * sizeof(double));
    double big = 0;
    for (size_t i = 0; i < 3 * g->n; i++) big = fmax(big, fabs(g->xyz[i]));
    frexp(big, &c->unit_exp);
    return LH_OK;
}

/* The facet pairs that intersect, when opt->check_intersections: an error naming
 * the first few (lh_plc_intersections lists them all). */
static lh_status intersections(t3_ctx *c)
{
    enum { SHOWN = 8 };
    lh_index pairs[2 * SHOWN];
    size_t count = 0;
    if (!c->opt->check_intersections || c->g->facet_count < 2) return LH_OK;
    lh_status st = lh_plc_intersections(c->g, c->opt->alloc, SHOWN, pairs, &count, c->err);
    if (st != LH_OK || count == 0) return st;
    char list[256] = "";
    size_t len = 0, shown = count < SHOWN ? count : SHOWN;
    long base = c->g->first_index;
    for (size_t i = 0; i < shown && len < sizeof list; i++)
        len += (size_t)snprintf(list + len, sizeof list - len, "%s%ld and %ld", i ? ", " : "",
                                (long)pairs[2 * i] + base, (long)pairs[2 * i + 1] + base);
    return lh__t3_say(c, LH_ERR_INTERSECTING_FACETS, 0,
                      "%zu pair%s of facets intersect: %s%s (-d lists them)", count,
                      count == 1 ? "" : "s", list, count > shown ? ", ..." : "");
}

static lh_status constraints(t3_ctx *c, size_t *nonplanar)
{
    lh__facet_tris ft;
    lh_status st = lh__facets_triangulate(c->g, &c->al, &ft, c->err);
    if (st != LH_OK) return st;
    *nonplanar = ft.nonplanar;
    st = lh__t3_constraints(c, &ft);
    lh__facet_tris_free(&c->al, &ft);
    if (st != LH_OK) return st;
    c->node_first = lh__alloc(&c->al, (c->seg_count + 1) * sizeof(lh_index)); /* no nodes yet */
    if (!c->node_first) return lh__t3_say(c, LH_ERR_NOMEM, 0, "out of memory");
    memset(c->node_first, 0, (c->seg_count + 1) * sizeof(lh_index));
    c->seg_seen = lh__alloc(&c->al, (c->seg_count + 1) * sizeof(uint32_t));
    c->patch_seen = lh__alloc(&c->al, (c->patch_count + 1) * sizeof(uint32_t));
    c->cover_first = lh__alloc(&c->al, (c->patch_count + 1) * sizeof(lh_index));
    c->cover_len = lh__alloc(&c->al, (c->patch_count + 1) * sizeof(lh_index));
    if (!c->seg_seen || !c->patch_seen || !c->cover_first || !c->cover_len)
        return lh__t3_say(c, LH_ERR_NOMEM, 0, "out of memory");
    memset(c->seg_seen, 0, (c->seg_count + 1) * sizeof(uint32_t));
    memset(c->patch_seen, 0, (c->patch_count + 1) * sizeof(uint32_t));
    for (size_t k = 0; k <= c->patch_count; k++) c->cover_first[k] = -1, c->cover_len[k] = 0;
    st = lh__t3_mesh_load(c);
    return st == LH_OK ? lh__t3_stars(c) : st;
}

/* The domain carved (carve.c); then the boundary Steiner points taken off the
 * boundary (recover_suppress.c: all of them with -Y, else those that need no more
 * points inside the domain than they were), and, when any was, the domain carved
 * again. */
static lh_status domain(t3_ctx *c, t3_domain *d)
{
    lh_status st = lh__t3_walls(c, d);
    if (st == LH_OK) st = lh__t3_carve(c, d);
    const int refined = c->refine_points > 0 && c->opt->boundary_steiner;
    if (st != LH_OK || c->steiner == 0 || refined) return st; /* refinement's stay */
    unsigned char *out = lh__alloc(&c->al, c->tet_count + 1);
    if (!out) return lh__t3_say(c, LH_ERR_NOMEM, 0, "out of memory");
    for (size_t t = 0; t < c->tet_count; t++) out[t] = d->label[t] == T3_OUT;
    size_t taken;
    st = lh__t3_recover_suppress(c, out, &taken);
    lh__free(&c->al, out);
    if (st != LH_OK || taken == 0) return st;
    lh__t3_domain_free(c, d);
    st = lh__t3_walls(c, d);
    return st == LH_OK ? lh__t3_carve(c, d) : st;
}

static lh_status mesh(t3_ctx *c, lh_tetmesh **out)
{
    size_t nonplanar = 0;
    lh_status st = lh__t3_plc_check(c);
    if (st == LH_OK) st = intersections(c);
    if (st == LH_OK) st = start(c);
    if (st == LH_OK) st = constraints(c, &nonplanar);
    if (st == LH_OK) st = lh__t3_recover(c);
    if (st == LH_OK) st = lh__t3_refine(c);
    t3_domain d;
    memset(&d, 0, sizeof d);
    if (st == LH_OK) st = domain(c, &d);
    if (st == LH_OK) st = lh__t3_partly_carved(c, &d);
    lh_tetmesh *m = NULL;
    if (st == LH_OK && !(m = lh__tetmesh_new(&c->al)))
        st = lh__t3_say(c, LH_ERR_NOMEM, 0, "out of memory");
    if (st == LH_OK) st = lh__t3_output(c, &d, m);
    lh__t3_domain_free(c, &d);
    if (st != LH_OK) {
        lh_tetmesh_free(m);
        return st;
    }
    m->stats.facets_nonplanar = nonplanar;
    m->stats.refine_points = c->refine_points;
    m->stats.over_volume = c->over_volume;
    m->stats.over_size = c->over_size;
    lh__tetmesh_quality(m, c->opt->max_radius_edge, c->opt->min_dihedral);
    if (c->left && (st = lh__t3_leftovers(c, m)) != LH_OK) {
        lh_tetmesh_free(m);
        return st;
    }
    if (c->opt->second_order && (st = lh__tetmesh_second_order(m)) != LH_OK) {
        lh_tetmesh_free(m);
        return lh__t3_say(c, st, 0, st == LH_ERR_NOMEM ? "out of memory" : "too many second-order nodes");
    }
    *out = m;
    return LH_OK;
}

lh_status lh_tetrahedralize(const lh_plc *g, const lh_tetmesh_options *opt, lh_tetmesh **out,
                            lh_error *err)
{
    lh__error_clear(err);
    if (out) *out = NULL;
    lh_tetmesh_options defaults;
    lh_tetmesh_options_default(&defaults);
    if (!opt) opt = &defaults;
    t3_ctx c;
    memset(&c, 0, sizeof c);
    c.err = err, c.g = g, c.opt = opt;
    if (!g || !out || !lh__allocator_init(&c.al, opt->alloc) ||
        (opt->max_radius_edge != 0 && !(opt->max_radius_edge >= 1)) || !(opt->max_volume >= 0) ||
        !(opt->min_dihedral >= 0 && opt->min_dihedral < 90) || opt->optimize_passes < 0 ||
        opt->optimize_passes > 10)
        return lh__error_done(err, LH_ERR_INVALID_ARGUMENT);
    lh_status st = mesh(&c, out);
    ctx_free(&c);
    return lh__error_done(err, st);
}
