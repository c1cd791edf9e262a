/*
 * check_plc.h — what the two halves of lh_tetmesh_check's conformity test share:
 * check_plc.c (the PLC's consistency, exact helpers, segments, the entry) and
 * check_facets.c (every facet the union of its subfaces).
 */
#ifndef LH_CHECK_PLC_H
#define LH_CHECK_PLC_H

#include "check.h"

typedef struct hrec {
    lh_index from, to, sub;
} hrec;
typedef struct prec {
    lh_index a, b, pos;
} prec;

typedef struct pchk {
    lh__tchk *c;
    const lh_plc *g;
    size_t ns;        /* segments                                                */
    lh_index *seg;    /* 2 per segment                                            */
    lh_index *away;   /* segments with no subsegment that leave the mesh at both
                         ends: carved away if their facets are (check_away)       */
    size_t naway;
    hrec *h;          /* 2 per subsegment, sorted by (from, to)                   */
    lh_index *seg_of; /* per subsegment: the first segment whose chain has it     */
    lh_index *pt_seg; /* per point: the first segment whose chain passes it, -1   */
    lh_index *plane;  /* 3 per facet: first three non-collinear points, or -1     */
    int *axis;        /* per facet: the coordinate its projection drops           */
    unsigned char *planar;
    signed char *eps; /* per polygon: +1 area, -1 hole, 0 neither                 */
    lh_index *par;    /* per subface: its facet or -1                             */
    size_t *ffirst;   /* facet_count + 1 offsets into flist                       */
    lh_index *flist;  /* subfaces by facet                                        */
    prec *pe;         /* scratch: a facet's subface edges (3 per subface)         */
    prec *re;         /* scratch: a facet's polygon edges                         */
    lh__detsum *sum, *s2, *s1;
} pchk;

static inline size_t lh__pchk_poly_len(const lh_plc *g, size_t p)
{
    return (size_t)(g->polygon_first[p + 1] - g->polygon_first[p]);
}
static inline const lh_index *lh__pchk_poly_v(const lh_plc *g, size_t p)
{
    return g->polygon_vertices + g->polygon_first[p];
}

/* check_plc.c */
void lh__pchk_proj(const double *p, int axis, double *q);
int lh__pchk_orient3i(pchk *k, lh_index a, lh_index b, lh_index x, lh_index y);
int lh__pchk_collinear(pchk *k, const double *a, const double *b, const double *x);
int lh__pchk_in_facet(pchk *k, size_t f, const double (*q)[2], int m);
void lh__pchk_prepare_facets(pchk *k);
int lh__pchk_prec_cmp(const void *x, const void *y);
int lh__pchk_hrec_cmp(const void *x, const void *y);
int lh__pchk_near_plane(const double *a, const double *b, const double *c, const double *x);
void lh__pchk_mark_off(pchk *k, lh_index v);
int lh__pchk_strictly_between(double p, double x, double q);
/* check_facets.c: every facet the union of its subfaces ((a) and (b) above). */
lh_status lh__pchk_check_facets(pchk *k);

#endif
