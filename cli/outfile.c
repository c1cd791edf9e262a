/* outfile.c — whole-or-nothing output files (outfile.h). */
#define _POSIX_C_SOURCE 200809L /* mkstemp, fdopen, fchmod, link, lstat, umask */
#include "outfile.h"

#include "cli.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

int lh_cli_same_file(const char *a, const char *b)
{
    struct stat sa, sb;
    return a && b && stat(a, &sa) == 0 && stat(b, &sb) == 0 && sa.st_dev == sb.st_dev &&
           sa.st_ino == sb.st_ino;
}

/* A fresh PATH.tmpXXXXXX beside PATH, with the permissions a new PATH would get. */
static FILE *open_tmp(const char *path, char **tmp)
{
    size_t len = strlen(path);
    *tmp = malloc(len + sizeof ".tmpXXXXXX");
    if (!*tmp) return NULL;
    memcpy(*tmp, path, len);
    memcpy(*tmp + len, ".tmpXXXXXX", sizeof ".tmpXXXXXX");
    int fd = mkstemp(*tmp);
    if (fd < 0) return NULL;
    mode_t mask = umask(0);
    umask(mask);
    FILE *f = fdopen(fd, "w");
    if (!f || fchmod(fd, 0666 & ~mask) != 0) {
        int err = errno;
        if (f) fclose(f);
        else close(fd);
        unlink(*tmp);
        errno = err;
        return NULL;
    }
    return f;
}

int lh_cli_out_open(lh_cli_out *o, const char *cmd, const char *path, int replace,
                    const char *input)
{
    memset(o, 0, sizeof *o);
    if (!path || !strcmp(path, "-")) {
        o->f = stdout;
        return 1;
    }
    if (lh_cli_same_file(path, input)) {
        fprintf(stderr, "lifthull %s: '%s' is the input file; it is not overwritten\n", cmd, path);
        return 0;
    }
    /* Created or replaced through a temporary file when absent or a regular file;
     * anything else (a device, a pipe, a symbolic link) is written through, never
     * replaced. */
    struct stat st;
    int exists = lstat(path, &st) == 0, direct = exists && !S_ISREG(st.st_mode);
    if (exists && !replace) {
        fprintf(stderr, "lifthull %s: '%s' exists (use -f to replace it)\n", cmd, path);
        return 0;
    }
    o->f = direct ? fopen(path, "w") : open_tmp(path, &o->tmp);
    if (!o->f) {
        fprintf(stderr, "lifthull %s: cannot create '%s': %s\n", cmd, path, strerror(errno));
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
    if (!o->path) return ok ? lh_cli_finish_output(cmd) : LH_EXIT_FAIL;
    int err = 0;
    if (fflush(o->f) != 0 || ferror(o->f)) err = errno ? errno : EIO;
    if (fclose(o->f) != 0 && !err) err = errno ? errno : EIO;
    if (ok && !err && o->tmp && (o->replace ? rename(o->tmp, o->path) : link(o->tmp, o->path)) != 0)
        err = errno;
    if (o->tmp && (!o->replace || err || !ok)) unlink(o->tmp);
    free(o->tmp);
    o->tmp = NULL;
    if (ok && err == EEXIST)
        fprintf(stderr, "lifthull %s: '%s' exists (use -f to replace it)\n", cmd, o->path);
    else if (ok && err)
        fprintf(stderr, "lifthull %s: cannot write '%s': %s\n", cmd, o->path, strerror(err));
    return ok && !err ? LH_EXIT_OK : LH_EXIT_FAIL;
}
