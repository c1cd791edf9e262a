/* qhull_sides.h — facet sides paired by their vertex sets (qhull_sides.c). */
#ifndef LH_CLI_QHULL_SIDES_H
#define LH_CLI_QHULL_SIDES_H

#include "lifthull.h"

#define LH_CLI_NO_SIDE (-LH_INDEX_MAX - 1) /* lh_cli_pair_across: no facet across */

/* Within one family of m facets (nv vertices each): nbr[f*nv+k] = the facet sharing
 * side k of f, or -1. Returns 0 when out of memory. */
int lh_cli_pair_within(int nv, size_t m, const lh_index *vert, lh_index *nbr);

/* Across families: for every side of the first family with nbr < 0, the facet g of
 * the other family (mo facets, overt) whose open side (onbr < 0) has the same
 * vertices: nbr = -(g+1); LH_CLI_NO_SIDE when none has. Returns 0 when out of memory. */
int lh_cli_pair_across(int nv, size_t m, const lh_index *vert, lh_index *nbr, size_t mo,
                       const lh_index *overt, const lh_index *onbr);

#endif
