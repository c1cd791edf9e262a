/* pslg_load.c — reading a 2D meshing input for `triangle` and `mesh` (pslg_io.h):
 * Triangle's .poly (with its .node when the .poly lists no vertices), a .node point
 * set, or JSON polygon rings. */
#include "pslg_io.h"
#include "cli.h"
#include "outfile.h"

#include <stdlib.h>
#include <string.h>

/* A .poly whose vertices are in BASE.node: read that and hand its points over. */
static int attach_node(lh_cli_pslg *in, const char *base)
{
    char *node = lh_cli_path_ext(base, strlen(base), ".node");
    if (!node) return 0;
    lh_points pts;
    memset(&pts, 0, sizeof pts);
    FILE *f = lh_cli_open_input(node);
    lh_error err;
    lh_status st = f ? lh_points_read(f, node, LH_FORMAT_NODE, NULL, &pts, &err) : LH_ERR_IO;
    if (f) fclose(f);
    if (f && st != LH_OK)
        fprintf(stderr, "%s\n", err.message[0] ? err.message : lh_status_message(st));
    if (st == LH_OK && pts.d != 2) {
        fprintf(stderr, "%s: the points have %d coordinates, a .poly needs 2\n", node, pts.d);
        st = LH_ERR_DIMENSION;
    }
    if (st == LH_OK && (st = lh_pslg_take_points(&in->g, &pts)) != LH_OK)
        fprintf(stderr, "%s: %s\n", node, lh_status_message(st));
    lh_points_free(&pts);
    in->node_path = node; /* an input too: never written */
    return st == LH_OK;
}

/* A .node point set: its points become a PSLG without segments. */
static int load_node(lh_cli_pslg *in, FILE *f)
{
    lh_error err;
    lh_status st = lh_points_read(f, in->path, LH_FORMAT_NODE, NULL, &in->pts, &err);
    if (st != LH_OK) {
        fprintf(stderr, "%s\n", err.message[0] ? err.message : lh_status_message(st));
        return 0;
    }
    if (in->pts.d != 2) {
        fprintf(stderr, "%s: the points have %d coordinates; 2D meshing needs 2\n", in->path, in->pts.d);
        return 0;
    }
    in->g.n = in->pts.n;
    in->g.xy = in->pts.xyz;
    in->g.attr_count = in->pts.attr_count;
    in->g.attr = in->pts.attr;
    in->g.vertex_marker = in->pts.marker;
    in->g.first_index = in->pts.first_index;
    return 1;
}

int lh_cli_pslg_load(lh_cli_pslg *in, const char *path, const char *base, int kind)
{
    memset(in, 0, sizeof *in);
    in->path = path;
    in->kind = kind;
    FILE *f = lh_cli_open_input(path);
    if (!f) return 0;
    lh_error err;
    lh_status st = LH_OK;
    int ok;
    if (kind == LH_CLI_NODE) {
        ok = load_node(in, f);
    } else {
        st = kind == LH_CLI_RINGS ? lh_rings_read(f, path, NULL, &in->g, &err)
                                  : lh_poly_read(f, path, NULL, &in->g, &err);
        if (st != LH_OK)
            fprintf(stderr, "%s\n", err.message[0] ? err.message : lh_status_message(st));
        ok = st == LH_OK && (kind != LH_CLI_POLY || in->g.n > 0 || attach_node(in, base));
    }
    fclose(f);
    if (!ok) lh_cli_pslg_free(in);
    return ok;
}

void lh_cli_pslg_free(lh_cli_pslg *in)
{
    lh_pslg_free(&in->g);
    lh_points_free(&in->pts);
    lh_cells_free(&in->ele);
    free(in->area);
    free(in->node_path);
    memset(in, 0, sizeof *in);
}

void lh_cli_pslg_report(const lh_cli_pslg *in, const lh_error *err)
{
    if (err->line) /* the message starts with "LINE: " */
        fprintf(stderr, "%s:%s\n", in->path, err->message);
    else
        fprintf(stderr, "%s: %s\n", in->path,
                err->message[0] ? err->message : lh_status_message(err->status));
}

static int load_area(lh_cli_pslg *in, const char *path)
{
    FILE *f = lh_cli_open_input(path);
    if (!f) return 0;
    in->area = malloc((in->ele.count ? in->ele.count : 1) * sizeof *in->area);
    int ok = in->area != NULL;
    if (!ok) fprintf(stderr, "%s: out of memory\n", path);
    else ok = lh_cli_area_read(f, path, in->ele.count, in->area);
    fclose(f);
    return ok;
}

int lh_cli_pslg_load_mesh(lh_cli_pslg *in, const char *base, int area)
{
    char *path = lh_cli_path_ext(base, strlen(base), ".ele");
    if (!path) return 0;
    FILE *f = lh_cli_open_input(path);
    lh_error err;
    lh_status st = f ? lh_cells_read(f, path, in->g.n, NULL, &in->ele, &err) : LH_ERR_IO;
    if (f) fclose(f);
    if (f && st != LH_OK)
        fprintf(stderr, "%s\n", err.message[0] ? err.message : lh_status_message(st));
    if (st == LH_OK && in->ele.nv != 3) {
        fprintf(stderr, "%s: %d points a cell; a triangle mesh has 3\n", path, in->ele.nv);
        st = LH_ERR_PARSE;
    }
    int ok = st == LH_OK;
    if (ok) {
        in->g.cover = in->ele.v;
        in->g.cover_count = in->ele.count;
    }
    if (ok && area) {
        free(path);
        ok = (path = lh_cli_path_ext(base, strlen(base), ".area")) != NULL && load_area(in, path);
        in->g.cover_area = in->area;
    }
    free(path);
    return ok;
}
