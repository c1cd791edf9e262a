/*
 * carve.c — the domain: the recovered facet triangles' faces are walls; tetrahedra
 * reachable from the convex hull without crossing a wall are outside (unless
 * convex_hull, or the PLC has no facet), those reachable from a hole point are
 * holes, and each region point labels the tetrahedra it reaches (flood fill, as
 * TetGen; Si 2015, sec. 4.4).
 */
#include "carve.h"
#include "lh_sort.h"

#include <stdlib.h>
#include <string.h>

static int cmp_wall(const void *x, const void *y)
{
    const lh_index *a = x, *b = y;
    for (int k = 0; k < 3; k++)
        if (a[k] != b[k]) return a[k] < b[k] ? -1 : 1;
    return 0;
}

/* d->wall from the sorted walls (w of them, each face once): both tets of each wall
 * face found in the star of its point with the fewest tets. */
static lh_status mark_walls(t3_ctx *c, t3_domain *d, const lh_index *walls, size_t w)
{
    const size_t count = c->tet_count;
    const lh_index *s = c->tv;
    d->wall = lh__alloc(&c->al, (4 * count + 1) * sizeof(lh_index));
    if (!d->wall) return lh__t3_say(c, LH_ERR_NOMEM, 0, "out of memory");
    for (size_t i = 0; i < 4 * count; i++) d->wall[i] = -1;
    for (size_t i = 0; i < w; i++) {
        const lh_index *f = walls + 4 * i;
        lh_index lo = f[0];
        for (int k = 1; k < 3; k++)
            if (c->star_first[f[k] + 1] - c->star_first[f[k]] <
                c->star_first[lo + 1] - c->star_first[lo])
                lo = f[k];
        for (lh_index q = c->star_first[lo]; q < c->star_first[lo + 1]; q++) {
            const size_t t = (size_t)c->star[q];
            int in = 0, j = 0;
            for (int k = 0; k < 4; k++) {
                const lh_index v = s[4 * t + k];
                if (v == f[0] || v == f[1] || v == f[2])
                    in++;
                else
                    j = k;
            }
            if (in == 3) d->wall[4 * t + (size_t)j] = f[3];
        }
    }
    return LH_OK;
}

/* Walls: every recovered patch's faces, as sorted triples with the facet (4
 * indices a wall), sorted, each face once (the first triangle's facet); then each
 * tet's faces marked with them (d->wall). */
lh_status lh__t3_walls(t3_ctx *c, t3_domain *d)
{
    size_t cap = 0, w = 0;
    lh_index *walls = NULL;
    for (size_t k = 0; k < c->patch_count; k++) {
        const lh_index *f;
        size_t nf;
        lh_status st = lh__t3_patch_cover(c, k, &f, &nf);
        if (st == LH_OK && w + nf > cap) {
            size_t nc = 2 * (w + nf) + 64;
            lh_index *x = lh__alloc(&c->al, 4 * nc * sizeof(lh_index));
            if (!x)
                st = lh__t3_say(c, LH_ERR_NOMEM, 0, "out of memory");
            else {
                if (w) memcpy(x, walls, 4 * w * sizeof(lh_index));
                lh__free(&c->al, walls);
                walls = x, cap = nc;
            }
        }
        if (st != LH_OK) {
            lh__free(&c->al, walls);
            return st;
        }
        for (size_t i = 0; i < nf; i++, w++) {
            memcpy(walls + 4 * w, f + 3 * i, 3 * sizeof(lh_index));
            walls[4 * w + 3] = c->patch_facet[k];
        }
    }
    /* sorted by their points, the last first: stable, so equal faces keep facet order */
    for (int k = 2; w && k >= 0; k--) {
        lh_status st = lh__sort_by_index(&c->al, walls, w, 4 * sizeof(lh_index),
                                         (size_t)k * sizeof(lh_index), c->n);
        if (st != LH_OK) {
            lh__free(&c->al, walls);
            return lh__t3_say(c, st, 0, "out of memory");
        }
    }
    for (size_t i = 1; i < w; i++) /* facets given twice count once (recover_setup.c) */
        if (cmp_wall(walls + 4 * (i - 1), walls + 4 * i) == 0 &&
            walls[4 * (i - 1) + 3] != walls[4 * i + 3]) {
            const lh_index *f = walls + 4 * i, g = walls[4 * (i - 1) + 3];
            const long base = c->g->first_index;
            lh_status st = lh__t3_say(
                c, LH_ERR_INTERSECTING_FACETS, c->g->facet_line ? c->g->facet_line[f[3]] : 0,
                "facets %ld and %ld overlap: both are recovered with the face of points %ld "
                "%ld %ld (a facet that is not planar is the mesh faces spanning its polygons)",
                (long)g + base, (long)f[3] + base, (long)f[0] + base, (long)f[1] + base,
                (long)f[2] + base);
            lh__free(&c->al, walls);
            return st;
        }
    size_t u = 0;
    for (size_t i = 0; i < w; i++)
        if (u == 0 || cmp_wall(walls + 4 * (u - 1), walls + 4 * i) != 0)
            memmove(walls + 4 * u++, walls + 4 * i, 4 * sizeof(lh_index));
    lh_status st = mark_walls(c, d, walls, u);
    lh__free(&c->al, walls);
    return st;
}

lh_index lh__t3_wall_of(const t3_domain *d, size_t t, int j)
{
    return d->wall[4 * t + (size_t)j];
}

/* Floods from tet `seed` across faces that are not walls, giving unlabelled tets
 * `label`; the stack holds tet_count entries. */
static void flood(const t3_ctx *c, t3_domain *d, lh_index seed, lh_index label)
{
    const lh_index *nbr = c->tn;
    if (d->label[seed] != T3_FREE) return;
    size_t top = 0;
    d->label[seed] = label;
    d->stack[top++] = seed;
    while (top) {
        lh_index t = d->stack[--top];
        for (int j = 0; j < 4; j++) {
            lh_index u = nbr[4 * (size_t)t + j];
            if (u < 0 || d->label[u] != T3_FREE || lh__t3_wall_of(d, (size_t)t, j) >= 0)
                continue;
            d->label[u] = label;
            d->stack[top++] = u;
        }
    }
}

/* The tetrahedron holding point q, -1 outside the hull; *wall = the facet of a wall
 * q lies on (a face of that tet with orient 0), else -1. */
static lh_index locate(t3_ctx *c, const t3_domain *d, const double *q, lh_index *wall)
{
    lh_location loc;
    *wall = -1;
    if (lh_tri_locate(c->dt, q, -1, &loc) != LH_OK || loc.simplex < 0) return -1;
    lh_index near = c->vtet[lh_tri_simplices(c->dt)[4 * (size_t)loc.simplex]];
    lh_index t = lh__t3_mesh_walk(c, near, q);
    if (t < 0) return -1;
    for (int j = 0; j < 4; j++)
        if (lh__t3_mesh_side(c, (size_t)t, j, q) == 0) {
            lh_index f = lh__t3_wall_of(d, (size_t)t, j);
            if (f >= 0) *wall = f;
        }
    return t;
}

static lh_status seed_fail(t3_ctx *c, const char *what, size_t i, const size_t *lines,
                           lh_index facet)
{
    size_t line = lines ? lines[i] : 0;
    return lh__t3_say(c, LH_ERR_DEGENERATE, line,
                      "%s %zu lies on facet %ld: which side it seeds is undefined", what,
                      i + (size_t)c->g->first_index, (long)facet + c->g->first_index);
}

lh_status lh__t3_carve(t3_ctx *c, t3_domain *d)
{
    const lh_plc *g = c->g;
    size_t count = c->tet_count;
    const lh_index *nbr = c->tn;
    d->label = lh__alloc(&c->al, (count + 1) * sizeof(lh_index));
    d->stack = lh__alloc(&c->al, (count + 1) * sizeof(lh_index));
    if (!d->label || !d->stack) return lh__t3_say(c, LH_ERR_NOMEM, 0, "out of memory");
    for (size_t t = 0; t < count; t++) d->label[t] = T3_FREE;
    for (size_t h = 0; h < g->hole_count; h++) {
        lh_index wall, t = locate(c, d, g->holes + 3 * h, &wall);
        if (wall >= 0) return seed_fail(c, "hole", h, g->hole_line, wall);
        if (t < 0)
            d->holes_ignored++;
        else
            flood(c, d, t, T3_OUT);
    }
    /* without facets nothing bounds a domain: the convex hull is it (TetGen without -p) */
    int hull = c->opt->convex_hull || g->facet_count == 0;
    for (size_t t = 0; !hull && t < count; t++)
        for (int j = 0; j < 4; j++)
            if (nbr[4 * t + j] < 0 && lh__t3_wall_of(d, t, j) < 0)
                flood(c, d, (lh_index)t, T3_OUT);
    for (size_t r = 0; r < g->region_count; r++) {
        lh_index wall, t = locate(c, d, g->regions + 5 * r, &wall);
        if (wall >= 0) return seed_fail(c, "region", r, g->region_line, wall);
        if (t < 0 || d->label[t] != T3_FREE)
            d->regions_ignored++;
        else
            flood(c, d, t, (lh_index)r);
    }
    for (size_t t = 0; c->opt->regions_only && t < count; t++) /* the regions are the domain */
        if (d->label[t] == T3_FREE) d->label[t] = T3_OUT;
    for (size_t t = 0; t < count; t++) d->kept += d->label[t] != T3_OUT;
    if (d->kept == 0)
        return lh__t3_say(c, LH_ERR_DEGENERATE, 0,
                          "every tetrahedron was carved away: the facets enclose no volume "
                          "that a hole point does not empty");
    return LH_OK;
}

/* Whether face f (sorted) has a kept tet on a side. */
static int face_kept(const t3_ctx *c, const t3_domain *d, const lh_index *f)
{
    for (lh_index q = c->star_first[f[0]]; q < c->star_first[f[0] + 1]; q++) {
        const lh_index t = c->star[q], *v = c->tv + 4 * (size_t)t;
        int in = 0;
        for (int k = 0; k < 4; k++) in += v[k] == f[1] || v[k] == f[2];
        if (in == 2 && d->label[t] != T3_OUT) return 1;
    }
    return 0;
}

lh_status lh__t3_partly_carved(t3_ctx *c, const t3_domain *d)
{
    for (size_t k = 0; k < c->patch_count; k++) {
        const lh_index *f;
        size_t nf, kept = 0;
        lh_status st = lh__t3_patch_cover(c, k, &f, &nf);
        if (st != LH_OK) return st;
        for (size_t i = 0; i < nf; i++) kept += face_kept(c, d, f + 3 * i);
        if (kept == 0 || kept == nf) continue;
        lh_index facet = c->patch_facet[k];
        size_t line = c->g->facet_line ? c->g->facet_line[facet] : 0;
        return lh__t3_say(c, LH_ERR_DEGENERATE, line,
                          "facet %ld is only partly on the domain's boundary: its recovered "
                          "faces fold out of the domain (a facet that is not planar, whose "
                          "surface its polygons do not fix)",
                          (long)facet + c->g->first_index);
    }
    return LH_OK;
}

void lh__t3_domain_free(t3_ctx *c, t3_domain *d)
{
    lh__free(&c->al, d->wall);
    lh__free(&c->al, d->label);
    lh__free(&c->al, d->stack);
    memset(d, 0, sizeof *d);
}
