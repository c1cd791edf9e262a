/* io_out.c — what the writers share: checked output and the checks of a mesh view
 * (lifthull.h, "file formats"). */
#include "io_internal.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

void lh__outf(lh__out *o, const char *fmt, ...)
{
    if (o->failed) return;
    va_list ap;
    va_start(ap, fmt);
    if (vfprintf(o->f, fmt, ap) < 0) o->failed = 1;
    va_end(ap);
}

/* Room for one more field (a blank and 24 characters, the longest %.17g), writing
 * what the row holds when it is nearly full. */
static void row_room(lh__out *o, lh__row *r)
{
    if (r->len + 32 <= sizeof r->s) return;
    if (!o->failed && fwrite(r->s, 1, r->len, o->f) != r->len) o->failed = 1;
    r->len = 0;
}

void lh__row_int(lh__out *o, lh__row *r, long long v)
{
    row_room(o, r);
    if (r->len) r->s[r->len++] = ' ';
    r->len += lh__fmt_int(v, r->s + r->len);
}

void lh__row_dbl(lh__out *o, lh__row *r, double x)
{
    row_room(o, r);
    if (r->len) r->s[r->len++] = ' ';
    r->len += lh__fmt_g17(x, r->s + r->len, sizeof r->s - r->len);
}

void lh__row_end(lh__out *o, lh__row *r)
{
    r->s[r->len++] = '\n';
    if (!o->failed && fwrite(r->s, 1, r->len, o->f) != r->len) o->failed = 1;
    r->len = 0;
}

lh_status lh__out_status(lh__out *o)
{
    if (!o->failed && (fflush(o->f) != 0 || ferror(o->f))) o->failed = 1;
    return o->failed ? LH_ERR_IO : LH_OK;
}

void lh__out_point3(lh__out *o, const lh_mesh_view *m, size_t i)
{
    const double *p = m->xyz + i * (size_t)m->d;
    lh__outf(o, "%.17g %.17g %.17g", p[0], m->d > 1 ? p[1] : 0.0, m->d > 2 ? p[2] : 0.0);
}

/* A field name that needs no quoting in XML attributes nor in Gmsh's string tags. */
int lh__field_name_ok(const char *s)
{
    if (!*s) return 0;
    for (; *s; s++)
        if (*s <= ' ' || *s >= 0x7f || strchr("\"&<>'", *s)) return 0;
    return 1;
}

static lh_status check_arrays(const lh_mesh_view *m)
{
    size_t nd = m->n * (size_t)m->d, per = (size_t)m->k + 1;
    for (size_t i = 0; i < nd; i++)
        if (!isfinite(m->xyz[i])) return LH_ERR_NONFINITE;
    for (size_t i = 0; m->values && i < m->n; i++)
        if (!isfinite(m->values[i])) return LH_ERR_NONFINITE;
    for (size_t i = 0; i < m->count * per; i++) {
        if (m->cells[i] < 0 || (size_t)m->cells[i] >= m->n) return LH_ERR_INVALID_ARGUMENT;
        if (m->neighbors && (m->neighbors[i] < -1 || m->neighbors[i] >= (int64_t)m->count))
            return LH_ERR_INVALID_ARGUMENT;
    }
    return LH_OK;
}

lh_status lh__view_check(FILE *f, const lh_mesh_view *m, int dmin, int dmax, int kmin,
                         int kmax)
{
    if (!f || !m) return LH_ERR_INVALID_ARGUMENT;
    if (m->d < dmin || m->d > dmax || m->k < kmin || m->k > kmax) return LH_ERR_DIMENSION;
    if (m->n > LH_INDEX_MAX || m->count > LH_INDEX_MAX) return LH_ERR_TOO_LARGE;
    if ((m->n && !m->xyz) || (m->count && !m->cells)) return LH_ERR_INVALID_ARGUMENT;
    if (m->values_name && !lh__field_name_ok(m->values_name)) return LH_ERR_INVALID_ARGUMENT;
    return check_arrays(m);
}
