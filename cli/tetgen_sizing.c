/* tetgen_sizing.c — TetGen's -m (tetgen_io.h): the sizes of FILE.mtr at the input's
 * points, interpolated linearly in the Delaunay tetrahedralization of those points
 * (lh_tri_interpolate), the nearest point's size outside its hull, as the sizing
 * function of lh_tetmesh_options. */
#include "cli.h"
#include "tetgen_io.h"

#include <math.h>
#include <stdlib.h>

int lh_cli_sizing_load(lh_cli_sizing *s, const char *path, const lh_plc *g, const char *cmd)
{
    s->t = NULL;
    s->size = malloc((g->n ? g->n : 1) * sizeof *s->size);
    FILE *f = s->size ? lh_cli_open_input(path) : NULL;
    if (!s->size) fprintf(stderr, "lifthull %s: out of memory\n", cmd);
    int ok = f && lh_cli_mtr_read(f, path, g->n, s->size);
    if (f) fclose(f);
    lh_options opt;
    lh_options_default(&opt);
    lh_status st = ok ? lh_delaunay(3, g->n, g->xyz, &opt, &s->t) : LH_OK;
    if (st != LH_OK) {
        fprintf(
            stderr,
            "lifthull %s: %s: the sizes cannot be interpolated between the input's points: %s\n",
            cmd, path, lh_status_message(st));
        ok = 0;
    }
    if (!ok) lh_cli_sizing_free(s);
    return ok;
}

double lh_cli_sizing_at(void *user, const double xyz[3])
{
    lh_cli_sizing *s = user;
    double h = NAN;
    if (lh_tri_interpolate(s->t, LH_INTERP_LINEAR, 1, xyz, 1, s->size, &h) != LH_OK || isnan(h))
        if (lh_tri_interpolate(s->t, LH_INTERP_NEAREST, 1, xyz, 1, s->size, &h) != LH_OK) h = NAN;
    return h;
}

void lh_cli_sizing_free(lh_cli_sizing *s)
{
    lh_tri_free(s->t);
    free(s->size);
    s->t = NULL, s->size = NULL;
}
