/* consumer.c — uses an installed lifthull: exact orientation of a near-collinear
 * triple that plain doubles get wrong. Exit 0 when the answers are right. */
#include <lifthull.h>
#include <stdio.h>

int main(void)
{
    lh_pred *ctx;
    if (lh_pred_create(NULL, &ctx) != LH_OK) return 1;
    const double a[2] = {0.5 + 0x1p-53, 0.5}, b[2] = {12, 12}, c[2] = {24, 24};
    const double *p[3] = {a, b, c};
    int s = lh_orient(ctx, 2, p);
    lh_pred_free(ctx);
    printf("lifthull %s: orient = %d\n", lh_version_string(), s);
    return s == -1 ? 0 : 1;
}
