/* io_detect.c — LH_FORMAT_AUTO: the format from the name's extension, else from the
 * first lines of the input (the rules are stated at lh_points_read in lifthull.h). */
#include "io_internal.h"

#include <limits.h>
#include <stdlib.h>
#include <string.h>

typedef struct span {
    const unsigned char *p;
    size_t len;
} span;

/* What the detector needs to know of one line. */
typedef struct line_info {
    int numbers;        /* leading fields that are numbers (counted up to 3)    */
    int integer[2];     /* whether the first two of them are integers           */
    long long value[2]; /* and their values                                     */
    int text_after;     /* a non-number field follows the leading numbers       */
    int comma;          /* a ',' before any '#'                                 */
} line_info;

static int ends_with(const char *name, const char *ext)
{
    size_t n = strlen(name), e = strlen(ext);
    if (n < e) return 0;
    for (size_t i = 0; i < e; i++) {
        char c = name[n - e + i];
        if (c >= 'A' && c <= 'Z') c = (char)(c - 'A' + 'a');
        if (c != ext[i]) return 0;
    }
    return 1;
}

/* The next line that is neither blank nor a '#' comment, without its line end. Only
 * whole lines count (the last one too when the prefix is the whole input). */
static int next_line(const unsigned char *pre, size_t len, int complete, size_t *pos, span *out)
{
    while (*pos < len) {
        size_t a = *pos, b = a;
        while (b < len && pre[b] != '\n') b++;
        if (b == len && !complete) return 0;
        *pos = b + 1;
        while (a < b && (pre[a] == ' ' || pre[a] == '\t' || pre[a] == '\r')) a++;
        if (a == b || pre[a] == '#') continue;
        out->p = pre + a;
        out->len = b - a;
        return 1;
    }
    return 0;
}

/* Classifies a field (bytes f[0..n)) as a number and an integer. */
static int field_number(const unsigned char *f, size_t n, int *integer, long long *value)
{
    lh__token t;
    if (n > LH_READ_MAX_TOKEN) return 0;
    t.kind = LH__TOK_WORD;
    t.len = n;
    memcpy(t.text, f, n);
    t.text[n] = 0;
    double x;
    if (!lh__word_double(&t, &x)) return 0;
    *integer = lh__word_integer(&t, value);
    return 1;
}

static void analyse(span l, line_info *info)
{
    memset(info, 0, sizeof *info);
    size_t i = 0;
    int leading = 1;
    while (i < l.len && l.p[i] != '#') {
        if (l.p[i] == ' ' || l.p[i] == '\t' || l.p[i] == '\r') {
            i++;
            continue;
        }
        size_t a = i;
        while (i < l.len && l.p[i] != ' ' && l.p[i] != '\t' && l.p[i] != '\r' && l.p[i] != '#') {
            if (l.p[i] == ',' && info->numbers == 0) info->comma = 1; /* not in a comment after "d" */
            i++;
        }
        int integer = 0;
        long long v = 0;
        if (leading && info->numbers < 3 && field_number(l.p + a, i - a, &integer, &v)) {
            if (info->numbers < 2) {
                info->integer[info->numbers] = integer;
                info->value[info->numbers] = v;
            }
            info->numbers++;
        } else if (leading && info->numbers < 3) {
            leading = 0;
            info->text_after = info->numbers > 0;
        }
    }
}

/* A "d n" line could be a 2D point: whether the rest of a complete input reads as
 * two columns that do not hold the d*n coordinates Qhull would want. */
static int two_columns_instead(const unsigned char *pre, size_t len, size_t pos, long long d,
                               long long n)
{
    span l;
    line_info info;
    long long lines = 0;
    while (next_line(pre, len, 1, &pos, &l)) {
        analyse(l, &info);
        if (info.numbers != 2 || info.text_after || info.comma) return 0;
        lines++;
    }
    return n > LLONG_MAX / d || 2 * lines != d * n; /* d*n would overflow: not 2*lines */
}

lh_format lh__format_detect(const char *name, const unsigned char *pre, size_t len,
                            int complete)
{
    if (ends_with(name, ".node")) return LH_FORMAT_NODE;
    if (ends_with(name, ".csv")) return LH_FORMAT_COLUMNS;
    size_t pos = len >= 3 && pre[0] == 0xEF && pre[1] == 0xBB && pre[2] == 0xBF ? 3 : 0;
    span l;
    line_info h;
    if (!next_line(pre, len, complete, &pos, &l)) return LH_FORMAT_QHULL;
    analyse(l, &h);
    if (h.comma) return LH_FORMAT_COLUMNS;
    if (h.numbers == 0) { /* a title (Qhull) or column names (columns): look further */
        if (!next_line(pre, len, complete, &pos, &l)) return LH_FORMAT_QHULL;
        analyse(l, &h);
        if (h.comma) return LH_FORMAT_COLUMNS;
    }
    if (h.numbers == 0) return LH_FORMAT_QHULL; /* its reader says what is wrong */
    if (!h.integer[0]) return LH_FORMAT_COLUMNS;
    if (h.numbers == 1) return LH_FORMAT_QHULL;
    if (h.numbers > 2 || !h.integer[1]) return LH_FORMAT_COLUMNS;
    long long d = h.value[0], n = h.value[1];
    if (d < LH_DELAUNAY_MIN_DIM || d > LH_DELAUNAY_MAX_DIM || n < 1) return LH_FORMAT_COLUMNS;
    if (!h.text_after && complete && two_columns_instead(pre, len, pos, d, n))
        return LH_FORMAT_COLUMNS;
    return LH_FORMAT_QHULL;
}
