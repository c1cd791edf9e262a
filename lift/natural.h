/*
 * natural.h — the workspace of one natural-neighbour query (natural.c), shared with
 * the volume computation (natural_volumes.c). Internal to lift/.
 */
#ifndef LH_LIFT_NATURAL_H
#define LH_LIFT_NATURAL_H

#include "dt.h"

#include <stdint.h>

enum { NN_MAXD = 3, NN_MAXV = NN_MAXD + 1, NN_FIRST_CAP = 48 };

#define NN_EMPTY UINT64_MAX

/* A natural neighbour and its (not yet normalised) weight. */
typedef struct nn_pair {
    lh_index site;
    double w;
} nn_pair;

/* The work of one query. Conflict simplices have indices 0..nconf-1 (sorted by
 * simplex number, so the result does not depend on where the walk started), sites
 * of the conflict simplices ("local sites") 0..nsite-1. */
typedef struct nn_ws {
    size_t cap;        /* conflict simplices the arrays hold; sites: cap + d   */
    uint64_t *key;     /* open addressing: simplex s as 2s, site v as 2v+1     */
    lh_index *val;     /* simplex: conflict index or -1; site: local index     */
    size_t mask;       /* table size - 1                                       */
    size_t nconf, nsite;
    lh_index *conf;    /* cap: conflict simplices                              */
    lh_index *lv;      /* (d+1) per conflict simplex: its local sites          */
    lh_index *nb;      /* (d+1) per conflict simplex: neighbour's conflict
                          index, -1 for a non-conflict simplex or the hull     */
    uint8_t *done;     /* per conflict simplex: bit e, its edge e measured     */
    double *cc;        /* d per conflict simplex: circumcentre (relative to q) */
    double *fc;        /* (d+1)*d per conflict simplex: centre of q + facet j
                          where facet j is on the cavity's boundary            */
    lh_index *site;    /* per local site: its index in t                       */
    double *x;         /* d per local site: coordinates relative to q          */
    double *vol;       /* per local site: d * vol(S_i), accumulated            */
    double *aq;        /* per local site: area of q's new face with it         */
    double *root;      /* d per local site: a vertex of that face              */
    uint8_t *rooted;
    nn_pair *pair;     /* per local site: the result                           */
} nn_ws;

/* d * vol(S_i) of every local site into w->vol, from the conflict region indexed and
 * rescaled in w (natural_volumes.c). 0 when a circumcentre is singular in floating
 * point (q within rounding of the hull). */
int lh__nn_volumes(nn_ws *w, int d);

#endif
