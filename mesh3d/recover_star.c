/*
 * recover_star.c — the tetrahedra around each vertex of the current mesh (a CSR
 * array rebuilt after each insertion), and edge and face membership through them.
 */
#include "recover.h"

#include <stdint.h>

lh_status lh__t3_stars(t3_ctx *c)
{
    size_t n = c->n, count = c->tet_count;
    const lh_index *s = c->tv;
    lh__free(&c->al, c->star_first);
    lh__free(&c->al, c->star);
    c->star = NULL;
    c->star_first = lh__alloc(&c->al, (n + 1) * sizeof(lh_index));
    if (count > SIZE_MAX / (4 * sizeof(lh_index)) || !c->star_first)
        return lh__t3_say(c, LH_ERR_NOMEM, 0, "out of memory");
    c->star = lh__alloc(&c->al, (4 * count + 1) * sizeof(lh_index));
    if (!c->star) return lh__t3_say(c, LH_ERR_NOMEM, 0, "out of memory");
    lh_index *first = c->star_first;
    for (size_t v = 0; v <= n; v++) first[v] = 0;
    for (size_t i = 0; i < 4 * count; i++) first[s[i] + 1]++;
    for (size_t v = 0; v < n; v++) first[v + 1] += first[v];
    for (size_t t = 0; t < count; t++)
        for (int j = 0; j < 4; j++) c->star[first[s[4 * t + j]]++] = (lh_index)t;
    for (size_t v = n; v > 0; v--) first[v] = first[v - 1];
    first[0] = 0;
    return LH_OK;
}

static int tet_has(const lh_index *t, lh_index v)
{
    return t[0] == v || t[1] == v || t[2] == v || t[3] == v;
}

/* Each tet is checked for every point: after flips (recover_flip.c) the stars may
 * list a slot that now holds another tet. A tet found is in the mesh, so a yes is
 * still right then; a no may miss what flips made. */
int lh__t3_has_edge(const t3_ctx *c, lh_index p, lh_index q)
{
    const lh_index *s = c->tv;
    if (c->star_first[p + 1] - c->star_first[p] > c->star_first[q + 1] - c->star_first[q]) {
        lh_index x = p;
        p = q;
        q = x;
    }
    for (lh_index i = c->star_first[p]; i < c->star_first[p + 1]; i++)
        if (tet_has(s + 4 * (size_t)c->star[i], p) && tet_has(s + 4 * (size_t)c->star[i], q))
            return 1;
    return 0;
}

int lh__t3_has_face(const t3_ctx *c, lh_index a, lh_index b, lh_index d)
{
    const lh_index *s = c->tv;
    for (lh_index i = c->star_first[a]; i < c->star_first[a + 1]; i++) {
        const lh_index *t = s + 4 * (size_t)c->star[i];
        if (tet_has(t, a) && tet_has(t, b) && tet_has(t, d)) return 1;
    }
    return 0;
}
