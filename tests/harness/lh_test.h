/*
 * lh_test.h — lifthull's tiny test harness.
 *
 * A test file defines named test functions and lists them in main:
 *
 *     LH_TEST(orient_2_ccw) { LH_EXPECT_EQ_INT(lh_orient(ctx, 2, p), 1); }
 *     int main(int argc, char **argv) {
 *         static const lh_test_case cases[] = { LH_CASE(orient_2_ccw) };
 *         return lh_test_main(cases, LH_COUNT(cases), argc, argv);
 *     }
 *
 * Every assertion is declarative and prints both sides on failure. LH_EXPECT_*
 * records the failure and continues; LH_ASSERT_* records it and leaves the test.
 * `prog NAME...` runs only the named tests; `prog --list` lists them.
 * Exit status: 0 when every selected test passed, 1 otherwise.
 */
#ifndef LH_TEST_H
#define LH_TEST_H

#include <stdint.h>
#include <stdio.h>

typedef struct lh_test_state {
    const char *name;
    long failures;
    long checks;
} lh_test_state;

typedef void (*lh_test_fn)(lh_test_state *);
typedef struct lh_test_case {
    const char *name;
    lh_test_fn fn;
} lh_test_case;

#define LH_TEST(name) static void name(lh_test_state *lh_t_)
#define LH_CASE(name) {#name, name}
#define LH_COUNT(a) (sizeof(a) / sizeof((a)[0]))

int lh_test_main(const lh_test_case *cases, size_t count, int argc, char **argv);

/* Marsaglia's xorshift64 (13, 7, 17): advances *state (never 0) and returns it. The
 * tests' small deterministic streams; each test keeps its own state and seed. */
uint64_t lh_test_xorshift(uint64_t *state);

/* Reporting helpers (used by the macros). Return nonzero when the check passed. */
int lh_test_check_i64(lh_test_state *t, const char *file, int line, const char *op,
                      const char *ea, const char *eb, long long a, long long b);
int lh_test_check_u64(lh_test_state *t, const char *file, int line, const char *op,
                      const char *ea, const char *eb, unsigned long long a,
                      unsigned long long b);
int lh_test_check_dbl(lh_test_state *t, const char *file, int line, const char *op,
                      const char *ea, const char *eb, double a, double b);
int lh_test_check_str(lh_test_state *t, const char *file, int line, const char *ea,
                      const char *eb, const char *a, const char *b);
int lh_test_check_true(lh_test_state *t, const char *file, int line, const char *e,
                       int ok);
/* An allocator for lifthull's hooks (lh_allocator: alloc, free, user) that counts
 * live blocks and fails the fail_at-th allocation (0: never), for allocation-failure
 * tests. Use: lh_test_counter c = {0}; c.fail_at = k;
 *             lh_allocator a = {lh_test_counting_alloc, lh_test_counting_free, &c}; */
typedef struct lh_test_counter {
    long live, fail_at, calls;
} lh_test_counter;
void *lh_test_counting_alloc(void *user, size_t size);
void lh_test_counting_free(void *user, void *ptr);

/* A temporary file holding text[0..len) (NUL bytes allowed), rewound; NULL when the
 * system has no temporary files. The caller fcloses it (which removes it). */
FILE *lh_test_file(const char *text, size_t len);
/* The bytes of stack fn(arg) uses on a thread of its own, beyond what a thread that
 * does nothing uses (the thread's 1 MiB stack is painted first; the bytes no longer
 * painted were touched); 0 when the thread cannot be run. */
size_t lh_test_stack_used(void *(*fn)(void *), void *arg);

/* Adds a free-form note (e.g. the seed or the failing case) to the current test's
 * failure output. printf-style. */
void lh_test_note(lh_test_state *t, const char *fmt, ...);

#define LH_CHECK_I_(op, a, b) \
    lh_test_check_i64(lh_t_, __FILE__, __LINE__, #op, #a, #b, (long long)(a), (long long)(b))
#define LH_CHECK_U_(op, a, b)                                           \
    lh_test_check_u64(lh_t_, __FILE__, __LINE__, #op, #a, #b,          \
                      (unsigned long long)(a), (unsigned long long)(b))
#define LH_CHECK_D_(op, a, b) \
    lh_test_check_dbl(lh_t_, __FILE__, __LINE__, #op, #a, #b, (double)(a), (double)(b))

#define LH_EXPECT_EQ_INT(a, b) ((void)LH_CHECK_I_(==, a, b))
#define LH_EXPECT_NE_INT(a, b) ((void)LH_CHECK_I_(!=, a, b))
#define LH_EXPECT_LT_INT(a, b) ((void)LH_CHECK_I_(<, a, b))
#define LH_EXPECT_LE_INT(a, b) ((void)LH_CHECK_I_(<=, a, b))
#define LH_EXPECT_GT_INT(a, b) ((void)LH_CHECK_I_(>, a, b))
#define LH_EXPECT_GE_INT(a, b) ((void)LH_CHECK_I_(>=, a, b))
#define LH_EXPECT_EQ_U64(a, b) ((void)LH_CHECK_U_(==, a, b))
#define LH_EXPECT_LE_U64(a, b) ((void)LH_CHECK_U_(<=, a, b))
#define LH_EXPECT_GT_U64(a, b) ((void)LH_CHECK_U_(>, a, b))
#define LH_EXPECT_EQ_DBL(a, b) ((void)LH_CHECK_D_(==, a, b))
#define LH_EXPECT_LE_DBL(a, b) ((void)LH_CHECK_D_(<=, a, b))
#define LH_EXPECT_STREQ(a, b) \
    ((void)lh_test_check_str(lh_t_, __FILE__, __LINE__, #a, #b, (a), (b)))
#define LH_EXPECT_TRUE(e) ((void)lh_test_check_true(lh_t_, __FILE__, __LINE__, #e, !!(e)))

#define LH_ASSERT_EQ_INT(a, b) do { if (!LH_CHECK_I_(==, a, b)) return; } while (0)
#define LH_ASSERT_EQ_U64(a, b) do { if (!LH_CHECK_U_(==, a, b)) return; } while (0)
#define LH_ASSERT_TRUE(e) \
    do { if (!lh_test_check_true(lh_t_, __FILE__, __LINE__, #e, !!(e))) return; } while (0)
#define LH_NOTE(...) lh_test_note(lh_t_, __VA_ARGS__)
/* True when the current test has failed so far (to stop a long loop early). */
#define LH_FAILED() (lh_t_->failures != 0)

#endif
