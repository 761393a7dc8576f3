/* Round axis ticks: steps of 1, 2 or 5 x 10^k (the "nice numbers" of Heckbert, Graphics
 * Gems 1990), chosen as the finest such step that keeps the tick count in bounds. */
#include <stdio.h>
#include <string.h>

#include "products/draw/draw_internal.h"

/* Tick indices beyond this are not representable exactly enough to label. */
#define SK__MAX_TICK_INDEX 1e15

static int ticks_in(double lo, double hi, double step, long long *first)
{
    /* A tolerance of a billionth of a step keeps bounds that are tick values inside. */
    double a = ceil(lo / step - 1e-9), b = floor(hi / step + 1e-9);
    if (fabs(a) > SK__MAX_TICK_INDEX || fabs(b) > SK__MAX_TICK_INDEX) return -1;
    *first = (long long)a;
    double n = b - a + 1.0;
    return n < 0.0 ? 0 : (n > 1e9 ? 1000000000 : (int)n);
}

sk_ticks sk_nice_ticks(double lo, double hi, int max_count)
{
    sk_ticks t = {0};
    if (!isfinite(lo) || !isfinite(hi) || !(hi > lo) || !isfinite(hi - lo)) return t;
    if (max_count < 2) max_count = 2;
    static const double mantissas[3] = {1.0, 2.0, 5.0};
    int k = (int)floor(log10((hi - lo) / (double)max_count)) - 1;
    for (int tries = 0; tries < 12; tries++, k++) {
        for (int m = 0; m < 3; m++) {
            double step = mantissas[m] * pow(10.0, k);
            long long first = 0;
            int n = ticks_in(lo, hi, step, &first);
            if (n < 0) return t;
            if (n <= max_count) {
                t.step = step;
                t.first_index = first;
                t.count = n;
                t.decimals = k < 0 ? -k : 0;
                return t;
            }
        }
    }
    return t;
}

void sk_ticks_format(const sk_ticks *t, int i, char *buf, size_t size)
{
    if (!buf || size == 0) return;
    double v = sk_ticks_value(t, i);
    double mag = fmax(fabs(sk_ticks_value(t, 0)), fabs(sk_ticks_value(t, t->count - 1)));
    if (mag >= 1e7 || t->decimals > 6) {
        /* Exponent notation with one exponent for the axis ("1.5e7", "2.0e7") and as many
           mantissa digits as the step needs. */
        int e = (int)floor(log10(mag));
        int step_e = (int)floor(log10(t->step) + 1e-9);
        int digits = e - step_e;
        if (digits < 0) digits = 0;
        if (digits > 15) digits = 15;
        if (v == 0.0)
            snprintf(buf, size, "0");
        else
            snprintf(buf, size, "%.*fe%d", digits, v / pow(10.0, e), e);
    } else {
        snprintf(buf, size, "%.*f", t->decimals, v);
    }
    /* No "-0" (or "-0.00"): a negative sign only on nonzero values. */
    if (buf[0] == '-' && strspn(buf + 1, "0.") == strlen(buf + 1))
        memmove(buf, buf + 1, strlen(buf));
}
