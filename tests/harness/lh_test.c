/* lh_test.c — runner and reporters for lh_test.h. */
#define _POSIX_C_SOURCE 200809L /* pthread_attr_setstack */
#include "lh_test.h"

#include <pthread.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

/* Under valgrind a finished thread's stack is no longer addressable: reading its
 * paint back needs it declared defined again (memcheck's client request). */
#if defined(__has_include)
#if __has_include(<valgrind/memcheck.h>)
#include <valgrind/memcheck.h>
#define LH_TEST_MAKE_DEFINED(p, n) VALGRIND_MAKE_MEM_DEFINED(p, n)
#endif
#endif
#ifndef LH_TEST_MAKE_DEFINED
#define LH_TEST_MAKE_DEFINED(p, n) ((void)0)
#endif

enum { LH_TEST_MAX_REPORTS = 20 }; /* failure lines printed per test, then quiet */

static int report(lh_test_state *t, int ok)
{
    t->checks++;
    if (ok) return 1;
    t->failures++;
    return 0;
}

static int loud(const lh_test_state *t) { return t->failures <= LH_TEST_MAX_REPORTS; }

int lh_test_check_i64(lh_test_state *t, const char *file, int line, const char *op,
                      const char *ea, const char *eb, long long a, long long b)
{
    int ok = !strcmp(op, "==") ? a == b : !strcmp(op, "!=") ? a != b
           : !strcmp(op, "<") ? a < b : !strcmp(op, "<=") ? a <= b
           : !strcmp(op, ">") ? a > b : a >= b;
    if (!report(t, ok) && loud(t))
        fprintf(stderr, "%s:%d: %s: expected %s %s %s\n    left:  %lld\n    right: %lld\n",
                file, line, t->name, ea, op, eb, a, b);
    return ok;
}

int lh_test_check_u64(lh_test_state *t, const char *file, int line, const char *op,
                      const char *ea, const char *eb, unsigned long long a,
                      unsigned long long b)
{
    int ok = !strcmp(op, "==") ? a == b : !strcmp(op, "<=") ? a <= b : a > b;
    if (!report(t, ok) && loud(t))
        fprintf(stderr, "%s:%d: %s: expected %s %s %s\n    left:  %llu\n    right: %llu\n",
                file, line, t->name, ea, op, eb, a, b);
    return ok;
}

int lh_test_check_dbl(lh_test_state *t, const char *file, int line, const char *op,
                      const char *ea, const char *eb, double a, double b)
{
    int ok = !strcmp(op, "==") ? a == b : a <= b;
    if (!report(t, ok) && loud(t))
        fprintf(stderr, "%s:%d: %s: expected %s %s %s\n    left:  %.17g\n    right: %.17g\n",
                file, line, t->name, ea, op, eb, a, b);
    return ok;
}

int lh_test_check_str(lh_test_state *t, const char *file, int line, const char *ea,
                      const char *eb, const char *a, const char *b)
{
    int ok = a && b && !strcmp(a, b);
    if (!report(t, ok) && loud(t))
        fprintf(stderr, "%s:%d: %s: expected %s == %s\n    left:  \"%s\"\n    right: \"%s\"\n",
                file, line, t->name, ea, eb, a ? a : "(null)", b ? b : "(null)");
    return ok;
}

int lh_test_check_true(lh_test_state *t, const char *file, int line, const char *e, int ok)
{
    if (!report(t, ok) && loud(t))
        fprintf(stderr, "%s:%d: %s: expected true: %s\n", file, line, t->name, e);
    return ok;
}

FILE *lh_test_file(const char *text, size_t len)
{
    FILE *f = tmpfile();
    if (f && len && fwrite(text, 1, len, f) != len) {
        fclose(f);
        return NULL;
    }
    if (f) rewind(f);
    return f;
}

void lh_test_note(lh_test_state *t, const char *fmt, ...)
{
    if (!loud(t)) return;
    va_list ap;
    fprintf(stderr, "    note (%s): ", t->name);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
}

static int selected(const char *name, int argc, char **argv)
{
    if (argc < 2) return 1;
    for (int i = 1; i < argc; i++)
        if (!strcmp(argv[i], name)) return 1;
    return 0;
}

int lh_test_main(const lh_test_case *cases, size_t count, int argc, char **argv)
{
    if (argc == 2 && !strcmp(argv[1], "--list")) {
        for (size_t i = 0; i < count; i++) puts(cases[i].name);
        return 0;
    }
    size_t run = 0, failed = 0;
    for (size_t i = 0; i < count; i++) {
        if (!selected(cases[i].name, argc, argv)) continue;
        lh_test_state t = {cases[i].name, 0, 0};
        cases[i].fn(&t);
        run++;
        if (t.failures) {
            failed++;
            printf("FAIL %s (%ld of %ld checks failed)\n", t.name, t.failures, t.checks);
        } else {
            printf("ok   %s (%ld checks)\n", t.name, t.checks);
        }
        fflush(stdout);
    }
    if (run == 0) {
        fprintf(stderr, "no test selected\n");
        return 1;
    }
    printf("%zu passed, %zu failed\n", run - failed, failed);
    return failed ? 1 : 0;
}

void *lh_test_counting_alloc(void *user, size_t size)
{
    lh_test_counter *c = user;
    if (++c->calls == c->fail_at) return NULL;
    void *p = malloc(size);
    if (p) c->live++;
    return p;
}

void lh_test_counting_free(void *user, void *ptr)
{
    lh_test_counter *c = user;
    if (ptr) c->live--;
    free(ptr);
}

static void *nothing(void *arg) { return arg; }

/* Bytes of a painted stack that fn(arg) on a thread touched; 0 on failure. */
static size_t painted_use(void *(*fn)(void *), void *arg)
{
    enum { SIZE = 1 << 20, PAINT = 0xA5 };
    unsigned char *stack = aligned_alloc(4096, SIZE);
    if (!stack) return 0;
    memset(stack, PAINT, SIZE);
    pthread_attr_t attr;
    pthread_t th;
    size_t used = 0;
    if (pthread_attr_init(&attr) == 0) {
        if (pthread_attr_setstack(&attr, stack, SIZE) == 0 && pthread_create(&th, &attr, fn, arg) == 0 &&
            pthread_join(th, NULL) == 0) {
            LH_TEST_MAKE_DEFINED(stack, SIZE);
            size_t low = 0; /* the stack grows down from stack + SIZE */
            while (low < SIZE && stack[low] == PAINT) low++;
            used = SIZE - low;
        }
        pthread_attr_destroy(&attr);
    }
    free(stack);
    return used;
}

size_t lh_test_stack_used(void *(*fn)(void *), void *arg)
{
    const size_t base = painted_use(nothing, NULL), used = painted_use(fn, arg);
    return base && used > base ? used - base : 0;
}

uint64_t lh_test_xorshift(uint64_t *state)
{
    uint64_t x = *state;
    x ^= x << 13;
    x ^= x >> 7;
    x ^= x << 17;
    return *state = x;
}
