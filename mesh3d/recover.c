/*
 * recover.c — the rounds of boundary recovery (recover.h): split the subsegments
 * that are not edges; when none is left, the triangles that are not unions of faces;
 * insert; repeat until every constraint is in the mesh.
 */
#include "recover.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

lh_status lh__t3_say(t3_ctx *c, lh_status st, size_t line, const char *fmt, ...)
{
    if (!c->err) return st;
    char text[LH_ERROR_MESSAGE_MAX];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(text, sizeof text, fmt, ap);
    va_end(ap);
    if (line) {
        c->err->line = line;
        return lh__error_say(c->err, st, "%zu: %s", line, text);
    }
    return lh__error_say(c->err, st, "%s", text);
}

lh_status lh__t3_grow(t3_ctx *c, void **buf, size_t *cap, size_t count, size_t need, size_t size)
{
    if (need <= *cap) return LH_OK;
    size_t k = 2 * need + 16;
    void *x = lh__alloc(&c->al, k * size);
    if (!x) return lh__t3_say(c, LH_ERR_NOMEM, 0, "out of memory");
    if (count) memcpy(x, *buf, count * size);
    lh__free(&c->al, *buf);
    *buf = x, *cap = k;
    return LH_OK;
}

lh_status lh__t3_room(t3_ctx *c, lh_index **buf, size_t *cap, size_t need)
{
    return lh__t3_grow(c, (void **)buf, cap, *cap, need, sizeof(lh_index));
}

/* Queues a split of every subsegment that is not an edge of the mesh. */
static lh_status split_edges(t3_ctx *c)
{
    for (size_t s = 0; s < c->seg_count; s++) {
        size_t cl = (size_t)(c->node_first[s + 1] - c->node_first[s]) + 2;
        lh_status st = lh__t3_room(c, &c->vbuf, &c->vcap, cl);
        if (st != LH_OK) return st;
        lh__t3_chain(c, (lh_index)s, c->vbuf, c->vcap);
        if (c->seg_seen[s] && !lh__t3_seg_changed(c, s, c->seg_seen[s] - 1)) continue;
        /* splits are queued, not done: the chain stays as it is this round */
        int whole = 1;
        for (size_t i = 0; i + 1 < cl; i++) {
            if (lh__t3_has_edge(c, c->vbuf[i], c->vbuf[i + 1])) continue;
            whole = 0;
            if ((st = lh__t3_split(c, (lh_index)s, i)) != LH_OK) return st;
        }
        c->seg_seen[s] = whole ? (uint32_t)c->rounds + 1 : 0;
    }
    return LH_OK;
}

static lh_status split_faces(t3_ctx *c)
{
    for (size_t k = 0; k < c->patch_count; k++) {
        if (c->patch_seen[k] && !lh__t3_patch_changed(c, k, c->patch_seen[k] - 1)) continue;
        int ok;
        lh_status st = lh__t3_patch_check(c, k, 1, &ok);
        if (st != LH_OK) return st;
        c->patch_seen[k] = ok ? (uint32_t)c->rounds + 1 : 0;
    }
    return LH_OK;
}

/* Rounds of splitting before recovery gives up: each round halves the subsegments it
 * splits, so an input it would end on needs far fewer. */
#define T3_MAX_ROUNDS 400

/* The Steiner points allowed: the caller's bound, else a budget from the input's size
 * that no input this mesher ends on comes near (docs/meshing3d.md). */
static size_t budget(const t3_ctx *c)
{
    if (c->opt->max_steiner != (size_t)-1) return c->opt->max_steiner;
    return 20 * (c->n_input + c->tri_count) + 100000;
}

/* The error when rounds run out: the facets (up to 5) still not recovered. */
static lh_status stalled(t3_ctx *c)
{
    char list[160] = "";
    size_t len = 0, bad = 0;
    for (size_t k = 0; k < c->patch_count; k++) {
        int ok;
        lh_status st = lh__t3_patch_check(c, k, 0, &ok);
        if (st != LH_OK) return st;
        if (ok) continue;
        if (bad++ < 5 && len < sizeof list - 24)
            len += (size_t)snprintf(list + len, sizeof list - len, "%s%ld", bad > 1 ? ", " : "",
                                    (long)c->patch_facet[k] + c->g->first_index);
    }
    return lh__t3_say(c, LH_ERR_STEINER_LIMIT, 0,
                      "boundary recovery did not end in %d rounds (%zu Steiner points): "
                      "%zu facets still missing, e.g. %s%s",
                      T3_MAX_ROUNDS, c->steiner, bad, list, bad > 5 ? ", ..." : "");
}

/* Nothing found before is taken as still there. A round takes a constraint found
 * whole as still whole while its points' stars in the Delaunay tetrahedralization stay
 * as they were (lh__t3_commit marks them); the flips that recovered it are then
 * likely, not certain, to recover it again, so a round that finds nothing missing
 * checks everything again without that. */
void lh__t3_forget(t3_ctx *c)
{
    memset(c->seg_seen, 0, c->seg_count * sizeof(uint32_t));
    memset(c->patch_seen, 0, c->patch_count * sizeof(uint32_t));
    for (size_t k = 0; k < c->patch_count; k++) c->cover_first[k] = -1;
    c->cover_count = 0;
}

/* Every constraint is checked again, uncached, in the mesh suppression made. */
lh_status lh__t3_recover_suppress(t3_ctx *c, const unsigned char *out, size_t *taken)
{
    lh_status st = lh__t3_suppress(c, c->opt->boundary_steiner == 0, out, taken);
    if (st != LH_OK || *taken == 0) return st;
    lh__t3_forget(c);
    st = split_edges(c);
    if (st == LH_OK && c->new_count == 0) st = split_faces(c);
    if (st == LH_OK && c->new_count)
        st = lh__t3_say(c, LH_ERR_INTERNAL, 0, "a constraint lost in taking Steiner points off");
    return st;
}

lh_status lh__t3_recover_check(t3_ctx *c)
{
    lh_status st = split_edges(c);
    if (st == LH_OK && c->new_count == 0) st = split_faces(c);
    if (st != LH_OK || c->new_count == 0) return st;
    c->new_count = 0; /* the rounds queue their own splits, after flips */
    return lh__t3_recover(c);
}

lh_status lh__t3_recover(t3_ctx *c)
{
    for (const size_t first = c->rounds;;) {
        if (c->rounds - first == T3_MAX_ROUNDS) return stalled(c);
        lh_status st = lh__t3_flip(c);
        if (st == LH_OK) st = split_edges(c);
        if (st == LH_OK && c->new_count == 0) st = split_faces(c);
        if (st == LH_OK && c->new_count == 0) { /* everything afresh, uncached */
            lh__t3_forget(c);
            st = split_edges(c);
            if (st == LH_OK && c->new_count == 0) st = split_faces(c);
        }
        if (st != LH_OK) return st;
        if (c->new_count == 0) return LH_OK;
        if (c->steiner + c->new_count > budget(c))
            return lh__t3_say(c, LH_ERR_STEINER_LIMIT, 0,
                              "boundary recovery needs more than %zu Steiner points (-S)",
                              budget(c));
        c->rounds++;
        if ((st = lh__t3_commit(c)) != LH_OK) return st;
    }
}
