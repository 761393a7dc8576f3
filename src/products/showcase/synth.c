/* An additive piano tone. Partial n of a string of fundamental f0 is at
 *   f_n = n f0 sqrt(1 + B n^2)                  (stiff-string inharmonicity, Fletcher 1964)
 * with amplitude sin(n pi beta) / n (a hammer striking at 1/8 of the string, whose
 * felt rolls off the upper partials more for a soft blow), and decays in two stages, a
 * fast prompt sound and a slow aftersound (the coupled strings of a unison, Weinreich
 * 1977), each stage's time shorter for higher partials and higher notes; the damper ends
 * the tone after the key is released. Samples are computed block by block (each block
 * from its own start), so the sound is the same for any thread count. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "products/showcase/showcase_internal.h"

#define MAX_PARTIALS 32
#define BLOCK 4096
#define STRIKE_POINT 0.125 /* hammer at 1/8 of the speaking length */
#define ATTACK_S 0.002     /* onset smoothing (no click) */
#define AFTERSOUND 0.35    /* share of the slow stage */
#define PROMPT_RATIO 0.18  /* prompt sound's time / aftersound's */

static sk_synth_desc resolved(const sk_synth_desc *desc)
{
    sk_synth_desc d = desc ? *desc : (sk_synth_desc){0};
    sk_schema_apply_defaults(&sk__synth_schema, &d);
    if (d.inharmonicity < 0) d.inharmonicity = 0;
    return d;
}

static sk_result validate(const sk_synth_desc *d, sk_error *err)
{
    return sk_schema_check(&sk__synth_schema, d, "synth", err);
}

size_t sk_synth_length(const sk_melody *melody, const sk_synth_desc *desc)
{
    sk_synth_desc d = resolved(desc);
    return (size_t)ceil((sk_melody_end(melody) + d.tail_s) * d.sample_rate);
}

typedef struct tone {
    double start, end; /* seconds: onset, key release */
    double stop;       /* silent after this */
    int partials;
    double freq[MAX_PARTIALS], amp[MAX_PARTIALS], slow[MAX_PARTIALS], fast[MAX_PARTIALS];
} tone;

static void make_tone(const sk_note *n, const sk_synth_desc *d, tone *t)
{
    double f0 = 440.0 * pow(2.0, (n->key - 69) / 12.0);
    double velocity = n->velocity / 127.0;
    /* inharmonicity grows toward the treble (shorter, relatively stiffer strings) */
    double b = d->inharmonicity * pow(2.0, (n->key - 60) / 24.0);
    double decay = d->decay_s * pow(261.63 / f0, 0.6);
    double rolloff = 0.25 * (1.25 - velocity);
    t->start = n->start_s;
    t->end = n->start_s + n->duration_s;
    t->stop = t->end + 10 * d->release_s;
    t->partials = 0;
    double sum = 0;
    for (int k = 1; k <= MAX_PARTIALS; k++) {
        double f = k * f0 * sqrt(1 + b * k * k);
        if (f > 0.45 * d->sample_rate) break;
        int i = t->partials++;
        t->freq[i] = f;
        t->amp[i] = fabs(sin(k * SK_PI * STRIKE_POINT)) / k * exp(-rolloff * (k - 1));
        t->slow[i] = decay / (1 + 0.15 * (k - 1));
        t->fast[i] = PROMPT_RATIO * t->slow[i];
        sum += t->amp[i];
    }
    double level = d->gain * pow(velocity, 1.5) / (sum > 0 ? sum : 1);
    for (int i = 0; i < t->partials; i++) t->amp[i] *= level;
}

/* Adds tone t to out[0..count) of samples starting at sample s0. */
static void add_tone(const tone *t, const sk_synth_desc *d, size_t s0, size_t count, float *out,
                     double *work)
{
    double rate = d->sample_rate, dt = 1.0 / rate;
    double a = t->start * rate, b = t->stop * rate;
    size_t first = s0, last = s0 + count;
    if ((double)last <= a || (double)first >= b) return;
    if ((double)first < a) first = (size_t)ceil(a);
    if ((double)last > b) last = (size_t)ceil(b);
    if (first >= last) return;
    size_t m = last - first;
    for (size_t k = 0; k < m; k++) work[k] = 0;
    double t0 = first * dt - t->start;
    for (int p = 0; p < t->partials; p++) {
        double w = 2 * SK_PI * t->freq[p];
        double c = cos(w * dt), s = sin(w * dt);
        double re = cos(w * t0), im = sin(w * t0); /* the phase at the block's first sample */
        double slow = exp(-t0 / t->slow[p]), fast = exp(-t0 / t->fast[p]);
        double ks = exp(-dt / t->slow[p]), kf = exp(-dt / t->fast[p]);
        double amp = t->amp[p];
        for (size_t k = 0; k < m; k++) {
            work[k] += amp * ((1 - AFTERSOUND) * fast + AFTERSOUND * slow) * im;
            double nr = re * c - im * s;
            im = re * s + im * c;
            re = nr;
            slow *= ks;
            fast *= kf;
        }
    }
    for (size_t k = 0; k < m; k++) {
        double time = (first + k) * dt - t->start;
        double env = time < ATTACK_S ? 0.5 - 0.5 * cos(SK_PI * time / ATTACK_S) : 1.0;
        double after = (first + k) * dt - t->end;
        if (after > 0) env *= exp(-after / d->release_s);
        out[first + k - s0] += (float)(env * work[k]);
    }
}

sk_result sk_synth_render(const sk_melody *melody, const sk_synth_desc *desc, float *out,
                          size_t count, sk_error *err)
{
    sk_synth_desc d = resolved(desc);
    sk_result r = validate(&d, err);
    if (r != SK_OK) return r;
    int n = melody->note_count;
    tone *tones = calloc((size_t)(n > 0 ? n : 1), sizeof *tones);
    if (!tones) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for %d tones", n);
    for (int i = 0; i < n; i++) make_tone(&melody->notes[i], &d, &tones[i]);
    memset(out, 0, count * sizeof *out);
    long blocks = (long)((count + BLOCK - 1) / BLOCK);
    bool failed = false;
#pragma omp parallel if (blocks > 4)
    {
        double *work = malloc(BLOCK * sizeof *work);
        if (!work) {
#pragma omp atomic write
            failed = true;
        }
#pragma omp for schedule(dynamic, 1)
        for (long blk = 0; blk < blocks; blk++) {
            if (!work) continue;
            size_t s0 = (size_t)blk * BLOCK, m = count - s0 < BLOCK ? count - s0 : BLOCK;
            for (int i = 0; i < n; i++) add_tone(&tones[i], &d, s0, m, out + s0, work);
        }
        free(work);
    }
    free(tones);
    if (failed) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for the synthesis");
    for (size_t i = 0; i < count; i++) out[i] = out[i] > 1 ? 1 : (out[i] < -1 ? -1 : out[i]);
    return SK_OK;
}
