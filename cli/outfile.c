/* outfile.c — output sets written whole, together or not at all (outfile.h). */
#define _POSIX_C_SOURCE 200809L /* mkstemp, fdopen, fchmod, fsync, link, lstat, sigaction */
#include "outfile.h"

#include "cli.h"

#include <errno.h>
#include <pthread.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* ---- the table of temporaries the signal handler removes ------------------------ */

/* The one process-wide state of the tool (see outfile.h): the names of the temporary
 * files that exist now. Entries change only with the caught signals blocked, so the
 * handler never sees one half written; the names stay allocated while listed. */
enum { TEMP_SLOTS = 16 };
static char *volatile temps[TEMP_SLOTS];
static const int caught[] = {SIGHUP, SIGINT, SIGPIPE, SIGTERM, SIGXFSZ};
enum { n_caught = sizeof caught / sizeof caught[0] };

/* Async-signal-safe: unlink, signal and raise only. The signal stays blocked until the
 * handler returns, then the default action ends the process. */
static void on_signal(int sig)
{
    for (int i = 0; i < TEMP_SLOTS; i++) {
        char *p = temps[i];
        if (p) unlink(p);
    }
    signal(sig, SIG_DFL);
    raise(sig);
}

static void block_signals(sigset_t *old)
{
    sigset_t s;
    sigemptyset(&s);
    for (int i = 0; i < n_caught; i++) sigaddset(&s, caught[i]);
    pthread_sigmask(SIG_BLOCK, &s, old);
}

static void restore_signals(const sigset_t *old) { pthread_sigmask(SIG_SETMASK, old, NULL); }

/* Installs the handler for each caught signal that is not ignored (nohup, a shell's
 * background job: the caller's choice stands) nor handled by it already: the
 * disposition itself says whether this ran before, no flag is kept. */
static void install_handlers(void)
{
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal;
    sigemptyset(&sa.sa_mask);
    for (int i = 0; i < n_caught; i++) sigaddset(&sa.sa_mask, caught[i]);
    for (int i = 0; i < n_caught; i++) {
        struct sigaction old;
        if (sigaction(caught[i], NULL, &old) == 0 && old.sa_handler != SIG_IGN && old.sa_handler != on_signal)
            sigaction(caught[i], &sa, NULL);
    }
}

/* With the signals blocked: lists or unlists name. */
static int temp_register(char *name)
{
    for (int i = 0; i < TEMP_SLOTS; i++)
        if (!temps[i]) {
            temps[i] = name;
            return 1;
        }
    return 0;
}

static void temp_unregister(const char *name)
{
    for (int i = 0; i < TEMP_SLOTS; i++)
        if (temps[i] == name) temps[i] = NULL;
}

/* Removes the temporary file and forgets it. */
static void temp_remove(char *name)
{
    sigset_t old;
    block_signals(&old);
    unlink(name);
    temp_unregister(name);
    restore_signals(&old);
}

/* ---- names ------------------------------------------------------------------------ */

char *lh_cli_path_ext(const char *base, size_t len, const char *ext)
{
    const size_t n = strlen(ext);
    char *p = malloc(len + n + 1);
    if (!p) return NULL;
    memcpy(p, base, len);
    memcpy(p + len, ext, n + 1);
    return p;
}

int lh_cli_paths(const char *base, size_t len, const char *const *ext, const int *want, int n,
                 char **path)
{
    int ok = 1;
    for (int i = 0; i < n; i++) {
        path[i] = NULL;
        if (ok && (!want || want[i])) ok = (path[i] = lh_cli_path_ext(base, len, ext[i])) != NULL;
    }
    return ok;
}

void lh_cli_paths_free(char **path, int n)
{
    for (int i = 0; i < n; i++) free(path[i]);
}

/* ---- checks ----------------------------------------------------------------------- */

int lh_cli_same_file(const char *a, const char *b)
{
    struct stat sa, sb;
    return a && b && stat(a, &sa) == 0 && stat(b, &sb) == 0 && sa.st_dev == sb.st_dev &&
           sa.st_ino == sb.st_ino;
}

/* Whether path's directory exists and may get new entries; errno on failure. */
static int dir_writable(const char *path)
{
    const char *slash = strrchr(path, '/');
    if (!slash) return access(".", W_OK | X_OK) == 0;
    size_t len = slash == path ? 1 : (size_t)(slash - path);
    char *dir = malloc(len + 1);
    if (!dir) return 0;
    memcpy(dir, path, len);
    dir[len] = 0;
    struct stat st;
    int ok = stat(dir, &st) == 0 && (S_ISDIR(st.st_mode) || (errno = ENOTDIR, 0)) &&
             access(dir, W_OK | X_OK) == 0;
    int err = errno;
    free(dir);
    errno = err;
    return ok;
}

int lh_cli_out_check(const char *cmd, const char *path, int replace, const char *input)
{
    if (!path || !strcmp(path, "-")) return 1;
    struct stat st;
    if (!*path) {
        fprintf(stderr, "lifthull %s: the output file name is empty\n", cmd);
    } else if (lh_cli_same_file(path, input)) {
        fprintf(stderr, "lifthull %s: '%s' is the input file; it is not overwritten\n", cmd, path);
    } else if (path[strlen(path) - 1] == '/' || (stat(path, &st) == 0 && S_ISDIR(st.st_mode))) {
        fprintf(stderr, "lifthull %s: '%s' is a directory\n", cmd, path);
    } else if (lstat(path, &st) == 0 && !replace) {
        fprintf(stderr, "lifthull %s: '%s' exists (use -f to replace it)\n", cmd, path);
    } else if (!dir_writable(path)) {
        fprintf(stderr, "lifthull %s: cannot create '%s': %s\n", cmd, path, strerror(errno));
    } else {
        return 1;
    }
    return 0;
}

/* ---- the set ---------------------------------------------------------------------- */

void lh_cli_outset_init(lh_cli_outset *s, const char *cmd, int replace, const char *input)
{
    memset(s, 0, sizeof *s);
    s->cmd = cmd;
    s->replace = replace;
    s->input = input;
}

/* A fresh PATH.tmpXXXXXX beside PATH, listed for the signal handler, with mode `mode`.
 * NULL with errno set on failure (nothing left behind). */
static FILE *open_tmp(const char *path, mode_t mode, char **tmp)
{
    size_t len = strlen(path);
    *tmp = malloc(len + sizeof ".tmpXXXXXX");
    if (!*tmp) return NULL;
    memcpy(*tmp, path, len);
    memcpy(*tmp + len, ".tmpXXXXXX", sizeof ".tmpXXXXXX");
    install_handlers();
    sigset_t old;
    block_signals(&old);
    int fd = mkstemp(*tmp), listed = fd >= 0 && temp_register(*tmp);
    if (fd >= 0 && !listed) unlink(*tmp);
    restore_signals(&old);
    if (!listed) {
        if (fd >= 0) close(fd), errno = EMFILE;
        return NULL;
    }
    FILE *f = fdopen(fd, "w");
    if (!f || fchmod(fd, mode) != 0) {
        int err = errno;
        if (f) fclose(f);
        else close(fd);
        temp_remove(*tmp);
        errno = err;
        return NULL;
    }
    setvbuf(f, NULL, _IOFBF, (size_t)1 << 16); /* large meshes: fewer system calls */
    return f;
}

FILE *lh_cli_outset_add(lh_cli_outset *s, const char *path)
{
    if (!path || !strcmp(path, "-")) {
        s->to_stdout = 1;
        return stdout;
    }
    if (s->n == LH_CLI_OUTSET_MAX || !lh_cli_out_check(s->cmd, path, s->replace, s->input)) return NULL;
    lh_cli_outfile *o = &s->file[s->n];
    struct stat st;
    int exists = lstat(path, &st) == 0;
    if (exists && !S_ISREG(st.st_mode)) {
        o->f = fopen(path, "w"); /* a device, a pipe, a symbolic link: written through */
    } else {
        mode_t mask = umask(0);
        umask(mask);
        /* a replaced file keeps its permission bits (not set-user/group-ID) */
        mode_t mode = exists ? st.st_mode & 01777 : 0666 & ~mask;
        o->f = open_tmp(path, mode, &o->tmp);
    }
    if (!o->f) {
        fprintf(stderr, "lifthull %s: cannot create '%s': %s\n", s->cmd, path, strerror(errno));
        free(o->tmp);
        o->tmp = NULL;
        return NULL;
    }
    o->path = path;
    s->n++;
    return o->f;
}

/* Flushes, fsyncs and closes one file; 0 or the error number. */
static int finish_file(lh_cli_outfile *o)
{
    int err = 0;
    if (fflush(o->f) != 0 || ferror(o->f)) err = errno ? errno : EIO;
    if (!err && o->tmp && fsync(fileno(o->f)) != 0) err = errno;
    if (fclose(o->f) != 0 && !err) err = errno ? errno : EIO;
    o->f = NULL;
    return err;
}

/* Moves every temporary onto its target, with the signals blocked (a signal then
 * comes after the last rename). Returns 1, or 0 after printing the problem. */
static int commit(lh_cli_outset *s)
{
    sigset_t old;
    block_signals(&old);
    int i = 0, err = 0;
    for (; i < s->n && !err; i++) {
        lh_cli_outfile *o = &s->file[i];
        if (!o->tmp) continue;
        if (s->replace ? rename(o->tmp, o->path) != 0 : link(o->tmp, o->path) != 0) err = errno;
        if (!err && !s->replace) unlink(o->tmp);
        if (!err) {
            temp_unregister(o->tmp);
            free(o->tmp);
            o->tmp = NULL;
        }
    }
    restore_signals(&old);
    if (!err) return 1;
    const char *path = s->file[i - 1].path;
    if (err == EEXIST) fprintf(stderr, "lifthull %s: '%s' exists (use -f to replace it)\n", s->cmd, path);
    else fprintf(stderr, "lifthull %s: cannot write '%s': %s\n", s->cmd, path, strerror(err));
    for (int j = 0; j < i - 1; j++)
        if (s->file[j].tmp == NULL && s->file[j].path)
            fprintf(stderr, "lifthull %s: '%s' was written before the failure\n", s->cmd, s->file[j].path);
    return 0;
}

int lh_cli_outset_close(lh_cli_outset *s, int ok)
{
    int good = ok, told = 0;
    for (int i = 0; i < s->n; i++) {
        int err = finish_file(&s->file[i]);
        if (err && !told++) /* the first failed write, whether or not the caller saw it */
            fprintf(stderr, "lifthull %s: cannot write '%s': %s\n", s->cmd, s->file[i].path, strerror(err));
        if (err) good = 0;
    }
    if (good) good = commit(s);
    for (int i = 0; i < s->n; i++)
        if (s->file[i].tmp) {
            temp_remove(s->file[i].tmp);
            free(s->file[i].tmp);
            s->file[i].tmp = NULL;
        }
    s->n = 0;
    if (s->to_stdout && good) return lh_cli_finish_output(s->cmd);
    return good ? LH_EXIT_OK : LH_EXIT_FAIL;
}

int lh_cli_out_open(lh_cli_out *o, const char *cmd, const char *path, int replace,
                    const char *input)
{
    lh_cli_outset_init(&o->set, cmd, replace, input);
    o->f = lh_cli_outset_add(&o->set, path);
    if (!o->f) lh_cli_outset_close(&o->set, 0);
    return o->f != NULL;
}

int lh_cli_out_close(lh_cli_out *o, const char *cmd, int ok)
{
    (void)cmd;
    return lh_cli_outset_close(&o->set, ok);
}
