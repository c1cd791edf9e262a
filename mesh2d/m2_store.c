/*
 * m2_store.c — storage of the 2D mesh (m2.h): arrays that double when full, a free
 * list of triangle slots, visit epochs, and the exact predicates on its points.
 */
#include <math.h>
#include <string.h>

#include "m2.h"

/* Replaces *arr (count elements of size esz) by a copy with room for cap. */
static int grow(lh__m2 *m, void **arr, size_t count, size_t cap, size_t esz)
{
    if (cap > SIZE_MAX / esz) return 0;
    void *q = lh__alloc(&m->al, cap * esz);
    if (!q) return 0;
    if (count) memcpy(q, *arr, count * esz);
    lh__free(&m->al, *arr);
    *arr = q;
    return 1;
}

static size_t next_cap(size_t cap, size_t need)
{
    size_t c = cap ? cap : 16;
    while (c < need) c = c > SIZE_MAX / 2 ? need : 2 * c;
    return c;
}

int lh__m2_grow_slow(lh__m2 *m, void **arr, size_t count, size_t *cap, size_t need, size_t esz)
{
    const size_t c = next_cap(*cap, need);
    if (!grow(m, arr, count, c, esz)) return 0;
    *cap = c;
    return 1;
}

static lh_status reserve_points(lh__m2 *m, size_t need)
{
    if (need <= m->cap_p) return LH_OK;
    if (need >= (size_t)LH_INDEX_MAX) return LH_ERR_TOO_LARGE;
    const size_t c = next_cap(m->cap_p, need), n = m->np;
    if (!grow(m, (void **)&m->xy, 2 * n, 2 * c, sizeof(double)) ||
        !grow(m, (void **)&m->pseg, n, c, sizeof(lh_index)) ||
        !grow(m, (void **)&m->vt, n, c, sizeof(lh_index)) ||
        !grow(m, (void **)&m->pmark, n, c, sizeof(lh_index)) ||
        (m->attr_count && !grow(m, (void **)&m->attr, n * (size_t)m->attr_count,
                                c * (size_t)m->attr_count, sizeof(double))))
        return LH_ERR_NOMEM;
    m->cap_p = c;
    return LH_OK;
}

lh_status lh__m2_init(lh__m2 *m, const lh_allocator *al, size_t n, const double *xy,
                      int attr_count, const double *attr, const lh_index *marker)
{
    memset(m, 0, sizeof *m);
    m->al = *al;
    m->free_head = -1;
    m->walk_hint = -1;
    m->attr_count = attr_count;
    lh_status st = lh_pred_create(al, &m->pred);
    if (st != LH_OK) return st;
    if ((st = reserve_points(m, n + n / 4 + 16)) != LH_OK) return st;
    memcpy(m->xy, xy, 2 * n * sizeof(double));
    for (size_t i = 0; i < n; i++) {
        m->pseg[i] = -1;
        m->vt[i] = -1;
        m->pmark[i] = marker ? marker[i] : 0;
    }
    if (attr_count) memcpy(m->attr, attr, n * (size_t)attr_count * sizeof(double));
    m->np = m->n_input = n;
    return LH_OK;
}

void lh__m2_free(lh__m2 *m)
{
    void *arrs[] = {m->xy, m->pseg, m->vt, m->attr, m->pmark, m->v, m->nb, m->sg,
                    m->tattr, m->tarea, m->mark, m->sv, m->sp, m->smul};
    for (size_t i = 0; i < sizeof arrs / sizeof arrs[0]; i++) lh__free(&m->al, arrs[i]);
    lh_pred_free(m->pred);
    memset(m, 0, sizeof *m);
}

lh_status lh__m2_add_point(lh__m2 *m, const double p[2], lh_index *out)
{
    lh_status st = reserve_points(m, m->np + 1);
    if (st != LH_OK) return st;
    const size_t i = m->np++;
    m->xy[2 * i] = p[0];
    m->xy[2 * i + 1] = p[1];
    m->pseg[i] = -1;
    m->vt[i] = -1;
    m->pmark[i] = 0;
    for (int a = 0; a < m->attr_count; a++) m->attr[i * (size_t)m->attr_count + a] = 0;
    *out = (lh_index)i;
    return LH_OK;
}

lh_status lh__m2_reserve_tris(lh__m2 *m, size_t more)
{
    if (m->cap_t - m->live >= more) return LH_OK; /* free slots: the list and the tail */
    const size_t need = m->nt + more;
    if (need >= (size_t)LH_INDEX_MAX / 4) return LH_ERR_TOO_LARGE;
    const size_t c = next_cap(m->cap_t, need), n = m->nt;
    if (!grow(m, (void **)&m->v, 3 * n, 3 * c, sizeof(lh_index)) ||
        !grow(m, (void **)&m->nb, 3 * n, 3 * c, sizeof(lh_index)) ||
        !grow(m, (void **)&m->sg, 3 * n, 3 * c, sizeof(lh_index)) ||
        !grow(m, (void **)&m->mark, n, c, sizeof(uint32_t)) ||
        (m->tattr && !grow(m, (void **)&m->tattr, n, c, sizeof(double))) ||
        (m->tarea && !grow(m, (void **)&m->tarea, n, c, sizeof(double))))
        return LH_ERR_NOMEM;
    m->cap_t = c;
    return LH_OK;
}

lh_index lh__m2_new_tri(lh__m2 *m)
{
    lh_index t;
    if (m->free_head >= 0) {
        t = m->free_head;
        m->free_head = m->nb[3 * (size_t)t];
    } else {
        t = (lh_index)m->nt++;
    }
    m->mark[t] = 0;
    m->live++;
    return t;
}

void lh__m2_kill_tri(lh__m2 *m, lh_index t)
{
    m->v[3 * (size_t)t] = -1;
    m->nb[3 * (size_t)t] = m->free_head;
    m->free_head = t;
    m->live--;
}

lh_status lh__m2_add_subseg(lh__m2 *m, lh_index a, lh_index b, lh_index parent,
                            lh_index *out)
{
    if (m->ns == m->cap_s) {
        const size_t c = next_cap(m->cap_s, m->ns + 1);
        if (c >= (size_t)LH_INDEX_MAX) return LH_ERR_TOO_LARGE;
        if (!grow(m, (void **)&m->sv, 2 * m->ns, 2 * c, sizeof(lh_index)) ||
            !grow(m, (void **)&m->sp, m->ns, c, sizeof(lh_index)) ||
            !grow(m, (void **)&m->smul, m->ns, c, sizeof(uint32_t)))
            return LH_ERR_NOMEM;
        m->cap_s = c;
    }
    const size_t s = m->ns++;
    m->sv[2 * s] = a;
    m->sv[2 * s + 1] = b;
    m->sp[s] = parent;
    m->smul[s] = 1;
    *out = (lh_index)s;
    return LH_OK;
}

uint32_t lh__m2_new_epoch(lh__m2 *m)
{
    if (++m->epoch == UINT32_MAX) {
        memset(m->mark, 0, m->nt * sizeof *m->mark);
        m->epoch = 1;
    }
    return m->epoch;
}

/*
 * The predicates on the mesh's points: a floating-point filter first (Shewchuk 1997,
 * "Adaptive precision floating-point arithmetic and fast robust geometric
 * predicates", §4.2-4.3: the error of the plain evaluation is below (3 + 16e)e resp.
 * (10 + 96e)e times the permanent, e = 2^-53), trusted only when the permanent is
 * finite and far above underflow (2^-900, where no product of the evaluation can have
 * lost digits); otherwise, and whenever the sign is not certain, the exact
 * predicates of lib/ decide (lh_orient, lh_insphere). Same answers, only faster.
 */
#define LH_EPS 1.1102230246251565e-16 /* 2^-53 */
#define LH_TINY 1.2e-271              /* ~2^-900 */

int lh__m2_orient_pt(const lh__m2 *m, lh_index a, lh_index b, const double *c)
{
    const double *pa = lh__m2_pt(m, a), *pb = lh__m2_pt(m, b);
    const double l = (pa[0] - c[0]) * (pb[1] - c[1]), r = (pa[1] - c[1]) * (pb[0] - c[0]);
    const double det = l - r, perm = fabs(l) + fabs(r);
    const double bound = (3 + 16 * LH_EPS) * LH_EPS * perm;
    if (perm > LH_TINY && perm < INFINITY) {
        if (det > bound) return 1;
        if (-det > bound) return -1;
    }
    const double *p[3] = {pa, pb, c};
    return lh_orient(m->pred, 2, p);
}

int lh__m2_orient(const lh__m2 *m, lh_index a, lh_index b, lh_index c)
{
    return lh__m2_orient_pt(m, a, b, lh__m2_pt(m, c));
}

int lh__m2_incircle(const lh__m2 *m, lh_index a, lh_index b, lh_index c, const double *d)
{
    const double *pa = lh__m2_pt(m, a), *pb = lh__m2_pt(m, b), *pc = lh__m2_pt(m, c);
    const double adx = pa[0] - d[0], ady = pa[1] - d[1], bdx = pb[0] - d[0], bdy = pb[1] - d[1];
    const double cdx = pc[0] - d[0], cdy = pc[1] - d[1];
    const double bc = bdx * cdy - cdx * bdy, ca = cdx * ady - adx * cdy, ab = adx * bdy - bdx * ady;
    const double al = adx * adx + ady * ady, bl = bdx * bdx + bdy * bdy, cl = cdx * cdx + cdy * cdy;
    /* lh_insphere's sign: < 0 inside for abc counterclockwise, the opposite of this
       determinant's (Shewchuk's incircle is > 0 inside) */
    const double det = al * bc + bl * ca + cl * ab;
    const double perm = (fabs(bdx * cdy) + fabs(cdx * bdy)) * al + (fabs(cdx * ady) + fabs(adx * cdy)) * bl +
                        (fabs(adx * bdy) + fabs(bdx * ady)) * cl;
    const double bound = (10 + 96 * LH_EPS) * LH_EPS * perm;
    if (perm > LH_TINY && perm < INFINITY) {
        if (det > bound) return -1;
        if (-det > bound) return 1;
    }
    const double *p[4] = {pa, pb, pc, d};
    return lh_insphere(m->pred, 2, p);
}
