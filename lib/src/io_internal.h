/*
 * io_internal.h — what the file-format modules share (lifthull.h, "file formats").
 *
 * Readers: a byte scanner over a replayed prefix and then the FILE, with the 1-based
 * line and column of every byte; tokens; one-line diagnostics "NAME:LINE:COL: expected
 * X, found Y"; number conversion; the growing arrays of lh_points.
 * Writers: checked output (every fprintf and ferror looked at) and the view's checks.
 */
#ifndef LH_IO_INTERNAL_H
#define LH_IO_INTERNAL_H

#include "lh_alloc.h"
#include "lh_error.h"
#include "lifthull.h"

#include <stdio.h>

/* ---- reading ---------------------------------------------------------------------- */

#define LH__IO_PREFIX 4096 /* bytes read ahead for LH_FORMAT_AUTO and the BOM */

typedef enum lh__tok_kind {
    LH__TOK_WORD,       /* text[0..len): bytes up to a blank, '#', EOL (or ',')   */
    LH__TOK_COMMA,      /* a ',' (only when the scanner splits at commas)         */
    LH__TOK_EOL,        /* the end of a line (only when asked not to cross lines) */
    LH__TOK_EOF,        /* the end of the input                                    */
    LH__TOK_LONG,       /* a word longer than LH_READ_MAX_TOKEN bytes              */
    LH__TOK_NUL,        /* a NUL byte                                              */
    LH__TOK_BYTE,       /* a byte that is not text (byte holds it)                 */
    LH__TOK_READ_ERROR  /* the FILE reported an error                              */
} lh__tok_kind;

typedef struct lh__token {
    lh__tok_kind kind;
    size_t line, col; /* where the token (or the end, or the bad byte) is */
    int byte;         /* LH__TOK_BYTE: the byte's value */
    size_t len;
    char text[LH_READ_MAX_TOKEN + 1]; /* NUL-terminated WORD */
} lh__token;

#define LH__SCAN_BLOCK 16384 /* bytes the scanner reads from the FILE at a time */
#define LH__READ_MAX_ATTR 1000 /* attributes a .node or .poly vertex may have */

/* Invariant: c is the byte at (line, col), or EOF past the end; bytes come from
 * pre[pre_pos..pre_len) first, then from f through block[block_pos..block_len).
 * It lives on the heap (lh__scan_open): the block and the scratch are too large for
 * the stack of a caller's thread, which may be small. */
typedef struct lh__scan {
    FILE *f;
    const unsigned char *pre;
    size_t pre_len, pre_pos;
    unsigned char block[LH__SCAN_BLOCK];
    size_t block_len, block_pos;
    int c;
    int read_error; /* ferror(f) was seen: c is EOF */
    int commas;     /* 1: ',' ends a word and is a token of its own */
    size_t line, col;
    size_t cr_col;  /* when c is '\n' right after '\r': the '\r''s column, else 0 */
    const char *name;
    lh_error *err;                     /* the caller's, may be NULL */
    lh_allocator al;                   /* what lh__scan_close frees it with */
    unsigned char head[LH__IO_PREFIX]; /* the bytes read ahead: pre points here */
    double attr[LH__READ_MAX_ATTR];    /* the readers' scratch: one item's attributes */
} lh__scan;

/* Starts scanning f on a scanner allocated with al: the first pre_want bytes (at most
 * LH__IO_PREFIX) are read ahead into s->head, s->pre_len of them (a UTF-8 BOM there
 * is skipped). NULL when out of memory, with "NAME:1:1: out of memory for the input
 * buffer" in err (may be NULL). */
lh__scan *lh__scan_open(FILE *f, size_t pre_want, const lh_allocator *al, const char *name,
                        lh_error *err);
/* Frees s (NULL: nothing). */
void lh__scan_close(lh__scan *s);
void lh__scan_advance(lh__scan *s);
/* Skips blanks and '#' comments, across line ends when cross_lines. */
void lh__scan_skip(lh__scan *s, int cross_lines);
/* Skips the rest of the current line, its line end included (a NUL stops it). */
void lh__scan_skip_line(lh__scan *s);
/* The next token; without cross_lines a line end is a token (LH__TOK_EOL, consumed). */
void lh__scan_next(lh__scan *s, int cross_lines, lh__token *t);
/* Whether byte c can start a number (digit, sign or '.'): Qhull's header rule. */
int lh__starts_number(int c);
/* Whether c, outside comments, is a text byte: printable ASCII or a blank. */
int lh__is_text(int c);

/* Writes "NAME:LINE:COL: expected WHAT, found FOUND[TAIL]" into s->err (its message,
 * line and column) and returns the status: st for a word or the end of the input or
 * line, LH_ERR_IO for a read error, LH_ERR_PARSE for a NUL, a non-text byte or a too
 * long token. */
lh_status lh__expected(lh__scan *s, lh_status st, const lh__token *t, const char *what,
                       const char *tail);
/* Writes "NAME:LINE:COL: TEXT" at t's position into s->err and returns st. */
lh_status lh__fail_at(lh__scan *s, lh_status st, const lh__token *t, const char *text);

/* A word that is a whole number for strtod: 1 and *x (possibly infinite or NaN), else 0. */
int lh__word_double(const lh__token *t, double *x);
/* text[0..len) (followed by a NUL) as strtod reads it: 1 and *x when strtod would
 * consume all of it, else 0; the same double, bit for bit (parse_double.c). */
int lh__parse_double(const char *text, size_t len, double *x);
/* The fast stages alone: 1 and strtod's *x when they decide, 0 when they cannot
 * (for tests: every decided value must be strtod's). */
int lh__parse_fast(const char *text, size_t len, double *x);
/* A word of an optional sign and decimal digits: 1 and *v (saturated at +-LLONG_MAX,
 * beyond every count and index limit of either index width), else 0. */
int lh__word_integer(const lh__token *t, long long *v);
/* For a word that is a non-finite number: writes "WHAT is 'TOKEN': NaN and infinities
 * are not NOUN" (or "... which overflows a double") and returns LH_ERR_NONFINITE. */
lh_status lh__nonfinite(lh__scan *s, const lh__token *t, const char *what,
                        const char *noun);

/* Reads token t as a finite number into *x. Errors: "expected WHAT, found the end of
 * the input[END_TAIL]" (or the line), "expected WHAT (a number), found ...", and
 * lh__nonfinite's. */
lh_status lh__number(lh__scan *s, const lh__token *t, const char *what, const char *noun,
                     const char *end_tail, double *x);
/* Reads token t as the dimension (2..8, the messages of Qhull's reader) or as a count
 * of points (1..LH_READ_MAX_POINTS) with the wording of `what`. */
lh_status lh__dimension(lh__scan *s, const lh__token *t, int *d);
lh_status lh__count(lh__scan *s, const lh__token *t, const char *what, size_t *n);
/* An optional small integer field (0..hi) of a header line (.node, .poly): the line's end
 * leaves *v as it is and sets *ended; once *ended is set, reads nothing. Error: "expected
 * WHAT, found ...". */
lh_status lh__header_field(lh__scan *s, const char *what, long long hi, int *v, int *ended);

/* The points being built: the output and its capacity in points. */
typedef struct lh__builder {
    lh_points *p;
    const lh_allocator *a;
    size_t cap;      /* points the arrays hold */
    size_t expected; /* declared count (growth stops there), 0 when unknown */
    int markers;     /* 1: one marker a point */
} lh__builder;

/* Appends one point (p->d coordinates, p->attr_count attributes, a marker when the
 * builder has markers), read at token `at`. On LH_ERR_NOMEM or LH_ERR_TOO_LARGE the
 * arrays are as they were and the message names the point. */
lh_status lh__push(lh__scan *s, lh__builder *b, const lh__token *at, const double *xyz,
                   const double *attr, lh_index marker);

/* The readers: s scans from the start of the input, b->p->d etc. are set by them. */
lh_status lh__read_qhull(lh__scan *s, lh__builder *b);
lh_status lh__read_node(lh__scan *s, lh__builder *b);
lh_status lh__read_columns(lh__scan *s, lh__builder *b);
/* LH_FORMAT_AUTO's choice from the name and the first len bytes of the input
 * (complete: those are the whole input). */
lh_format lh__format_detect(const char *name, const unsigned char *pre, size_t len,
                            int complete);

/* ---- writing ---------------------------------------------------------------------- */

/* Checked output: the first failure sticks. */
typedef struct lh__out {
    FILE *f;
    int failed;
} lh__out;

void lh__outf(lh__out *o, const char *fmt, ...)
#if defined(__GNUC__) || defined(__clang__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
/* LH_OK, or LH_ERR_IO if a write failed or ferror(f) is set. */
lh_status lh__out_status(lh__out *o);
/* Checks a view: NULL arrays, index ranges, finiteness, values_name; d in
 * dmin..dmax, k in kmin..kmax (LH_ERR_DIMENSION). */
lh_status lh__view_check(FILE *f, const lh_mesh_view *m, int dmin, int dmax, int kmin,
                         int kmax);
/* Whether s may name a field: printable ASCII, no blank, none of " & < > '. */
int lh__field_name_ok(const char *s);
/* A line of numbers built in memory and written with one fwrite: what printf would
 * write ("%lld", "%.17g", one blank between fields), without its cost per field. */
typedef struct lh__row {
    char s[512];
    size_t len;
} lh__row;
void lh__row_int(lh__out *o, lh__row *r, long long v);
void lh__row_dbl(lh__out *o, lh__row *r, double x);
/* fmt_number.c: v as printf's "%lld" writes it into out (room for 21 bytes, a
 * terminating NUL), and x as "%.17g" does, byte for byte (cap bytes); the length. */
size_t lh__fmt_int(long long v, char *out);
size_t lh__fmt_g17(double x, char *out, size_t cap);
/* Ends the line ('\n') and writes it; r is empty again. */
void lh__row_end(lh__out *o, lh__row *r);
/* Writes point i padded with zeros to 3 coordinates ("%.17g %.17g %.17g"). */
void lh__out_point3(lh__out *o, const lh_mesh_view *m, size_t i);

#endif
