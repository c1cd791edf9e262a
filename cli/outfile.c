/* outfile.c — whole-or-nothing output files (outfile.h). */
#define _POSIX_C_SOURCE 200809L /* mkstemp, fdopen, link */
#include "outfile.h"

#include "cli.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static int same_file(const char *a, const char *b)
{
    struct stat sa, sb;
    return a && b && stat(a, &sa) == 0 && stat(b, &sb) == 0 && sa.st_dev == sb.st_dev &&
           sa.st_ino == sb.st_ino;
}

int lh_cli_out_open(lh_cli_out *o, const char *cmd, const char *path, int replace,
                    const char *input)
{
    memset(o, 0, sizeof *o);
    if (!path || !strcmp(path, "-")) {
        o->f = stdout;
        return 1;
    }
    struct stat st;
    if (same_file(path, input)) {
        fprintf(stderr, "lifthull %s: %s: is the input file; it will not be overwritten\n", cmd, path);
        return 0;
    }
    if (!replace && stat(path, &st) == 0) {
        fprintf(stderr, "lifthull %s: %s: exists; not overwritten\n", cmd, path);
        return 0;
    }
    size_t len = strlen(path);
    o->tmp = malloc(len + 16);
    if (!o->tmp) {
        fprintf(stderr, "lifthull %s: out of memory\n", cmd);
        return 0;
    }
    memcpy(o->tmp, path, len);
    memcpy(o->tmp + len, ".tmpXXXXXX", 11);
    int fd = mkstemp(o->tmp);
    if (fd < 0 || !(o->f = fdopen(fd, "w"))) {
        fprintf(stderr, "lifthull %s: %s: %s\n", cmd, path, strerror(errno));
        if (fd >= 0) {
            close(fd);
            unlink(o->tmp);
        }
        free(o->tmp);
        o->tmp = NULL;
        return 0;
    }
    o->path = path;
    o->replace = replace;
    return 1;
}

int lh_cli_out_close(lh_cli_out *o, const char *cmd, int ok)
{
    if (!o->tmp) return ok ? lh_cli_finish_output(cmd) : LH_EXIT_FAIL;
    int err = fflush(o->f) != 0 || ferror(o->f);
    err |= fclose(o->f) != 0;
    int moved = 0;
    if (ok && !err) {
        moved = (o->replace ? rename(o->tmp, o->path) : link(o->tmp, o->path)) == 0;
        if (!moved) fprintf(stderr, "lifthull %s: %s: %s\n", cmd, o->path, strerror(errno));
    } else if (ok) {
        fprintf(stderr, "lifthull %s: %s: error writing the output\n", cmd, o->path);
    }
    if (!moved || !o->replace) unlink(o->tmp);
    free(o->tmp);
    o->tmp = NULL;
    return moved ? LH_EXIT_OK : LH_EXIT_FAIL;
}
