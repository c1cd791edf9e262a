/*
 * qhull_fields.c — Qhull's f ("all fields of all facets", a debugging dump) and FF
 * (the same without ridges), in Qhull 2020.2's layout, for qconvex and qdelaunay.
 * The subset printed is the one that exists for exact simplicial facets: the
 * vertices (with qdelaunay's lifted coordinate), and per facet the flag
 * "simplicial", the unit normal, the offset, the vertices and the neighbouring
 * facets. Qhull's other fields (top/bottom orientation, centrum, outside and
 * coplanar sets, ridges, merge state) describe its construction and precision
 * handling and have no counterpart here. Facet ids are the output's (f0, f1, ...),
 * then the other facets' (fm, fm+1, ... for the negative ids -1, -2, ...); vertex
 * ids are the site numbers plus one.
 */
#include "qhull.h"
#include "qhull_print.h"

#include <math.h>

void lh_cli_qprint_fields(FILE *f, const lh_cli_qopts *o, const lh_cli_qmodel *mo)
{
    const int lifted = o->prog != LH_QPROG_CONVEX;
    lh_cli_qlift s = lifted ? lh_cli_qlift_scale(mo) : (lh_cli_qlift){0, 1, 0};
    fputs("Vertices and facets:\n", f);
    for (size_t i = 0; i < mo->n; i++) {
        if (!lh_cli_qis_vertex(mo, i)) continue;
        fprintf(f, "- p%zu(v%zu):", i, i + 1);
        for (int j = 0; j < mo->d; j++) fprintf(f, " %5.2g", mo->xyz[i * mo->d + j]);
        if (lifted) fprintf(f, " %5.2g", lh_cli_qlifted(mo, s, i));
        fputc('\n', f);
    }
    for (size_t t = 0; t < mo->m; t++) {
        double n[LH_DELAUNAY_MAX_DIM + 1], off = 0;
        int e = 0;
        if (lifted) {
            lh_cli_qfacet_normal(mo, o, s, t, n);
            e = s.exp; /* every term below max |coordinate|: the sum on them scaled by 2^-e */
            for (int k = 0; k <= mo->d; k++) {
                size_t i = (size_t)mo->vert[t * mo->nv];
                off -= n[k] * (k < mo->d ? ldexp(mo->xyz[i * mo->d + k], -e) : lh_cli_qlifted_scaled(mo, s, i));
            }
        } else {
            lh_cli_qfacet_plane(mo, t, n, &off, &e);
        }
        fprintf(f, "- f%zu\n    - flags: simplicial\n    - normal: ", t);
        for (int j = 0; j < mo->d + lifted; j++) fprintf(f, " %8.4g", n[j]);
        fputs("\n    - offset: ", f);
        lh_cli_qscaled(f, 10, 7, off, e);
        fputs("\n    - vertices:", f);
        for (int k = 0; k < mo->nv; k++) {
            lh_index v = mo->vert[t * mo->nv + k];
            fprintf(f, " p%" LH_INDEX_PRI "(v%" LH_INDEX_PRI ")", v, v + 1);
        }
        fputs("\n    - neighboring facets:", f);
        for (int k = 0; k < mo->nv; k++) {
            lh_index g = mo->nbr[t * mo->nv + k];
            fprintf(f, " f%zu", g >= 0 ? (size_t)g : mo->m + (size_t)(-(g + 1)));
        }
        fputc('\n', f);
    }
}
