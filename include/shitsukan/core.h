/* shitsukan core: results and error details, deterministic random numbers,
 * gradient and fractal noise, threads and progress reporting.
 *
 * Thread-safety: every function here is thread-safe (no shared mutable state); an
 * sk_error or sk_progress_bar must not be shared between threads without care. */
#ifndef SHITSUKAN_CORE_H
#define SHITSUKAN_CORE_H

#include <stdarg.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "shitsukan/vecmath.h"

#ifdef __cplusplus
extern "C" {
#endif

#define SK_VERSION_MAJOR 0
#define SK_VERSION_MINOR 1
#define SK_VERSION_PATCH 0
#define SK_VERSION_STRING "0.1.0"

/* ------------------------------------------------------------------ results */

/* Every fallible call returns one of these and writes its outputs through pointers. */
typedef enum sk_result {
    SK_OK = 0,
    SK_ERROR_INVALID_ARGUMENT, /* a parameter is out of range, NaN/Inf or inconsistent */
    SK_ERROR_OUT_OF_MEMORY,    /* an allocation failed */
    SK_ERROR_LIMIT,            /* a size or count exceeds a stated cap */
    SK_ERROR_IO,               /* a file could not be opened, read, written or renamed */
    SK_ERROR_PARSE,            /* a file or string is malformed */
    SK_ERROR_UNSUPPORTED,      /* well-formed input using a feature not supported */
    SK_ERROR_NOT_FOUND,        /* a named file, preset, key or object does not exist */
    SK_ERROR_NUMERIC,          /* a numeric method failed (e.g. matrix not positive definite) */
    SK_RESULT_COUNT
} sk_result;

/* Stable lower-case name of a result, e.g. "invalid argument". Never NULL. */
const char *sk_result_string(sk_result result);

/* Caller-provided buffer for a human-readable detail: which field, what range.
 * Every call taking `sk_error *err` accepts NULL (no detail wanted). */
#define SK_ERROR_MESSAGE_SIZE 512
typedef struct sk_error {
    sk_result result;
    char message[SK_ERROR_MESSAGE_SIZE];
} sk_error;

/* Records `result` and a printf-style detail in `err` (if not NULL); returns `result`,
 * so library code can write `return sk_fail(err, SK_ERROR_..., "...", ...)`. */
sk_result sk_fail(sk_error *err, sk_result result, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;
sk_result sk_failv(sk_error *err, sk_result result, const char *fmt, va_list args);

/* Prefixes the message in `err` (if not NULL) with "prefix: " and sets err->result to
 * `result`, for adding context (a file name, a key path) on the way up. Returns `result`,
 * so a failure passes up in one line: `return sk_error_prefix(err, r, "%s", path);`. */
sk_result sk_error_prefix(sk_error *err, sk_result result, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/* Clears `err` to SK_OK with an empty message. */
void sk_error_clear(sk_error *err);

/* Range checks used by every desc validator. They fail with
 * "<name> = <value> is out of range [<lo>, <hi>]" or "<name> is not a finite number".
 * `name` is the full key path as the user wrote it (e.g. "levels[1].jitter"). */
sk_result sk_check_range_f(sk_error *err, const char *name, double value, double lo, double hi);
sk_result sk_check_range_i(sk_error *err, const char *name, long long value, long long lo,
                           long long hi);
sk_result sk_check_finite(sk_error *err, const char *name, double value);
/* The test of sk_check_range_f: finite and within [lo, hi]. Most values are stored as
 * float while their bounds are written as decimals (0.01, 0.99), so a value that equals a
 * bound once both are rounded to float counts as the bound (a stored 0.99f is accepted
 * for a documented maximum of 0.99). */
bool sk_in_range_f(double value, double lo, double hi);

/* Overflow-checked size arithmetic: returns false (and leaves *out untouched) on overflow. */
bool sk_size_mul(size_t a, size_t b, size_t *out);
bool sk_size_add(size_t a, size_t b, size_t *out);

/* ------------------------------------------------------ deterministic random */
/* Random values come from a hash of (seed, stable integer ids), never from a shared
 * sequential generator, so results are independent of thread count and evaluation
 * order. The mixer is a 64-bit finaliser of the SplitMix64 / Murmur3 family
 * (Steele, Lea, Flood 2014). */

static inline uint64_t sk_mix64(uint64_t z)
{
    z ^= z >> 30;
    z *= 0xbf58476d1ce4e5b9ULL;
    z ^= z >> 27;
    z *= 0x94d049bb133111ebULL;
    z ^= z >> 31;
    return z;
}

/* Hash of a seed and up to three ids; distinct argument tuples give independent bits. */
static inline uint64_t sk_hash(uint64_t seed, uint64_t a, uint64_t b, uint64_t c)
{
    uint64_t h = sk_mix64(seed + 0x9e3779b97f4a7c15ULL);
    h = sk_mix64(h ^ (a + 0x632be59bd9b4e019ULL));
    h = sk_mix64(h ^ (b + 0x85157af5b2b56a6dULL));
    h = sk_mix64(h ^ (c + 0xd6e8feb86659fd93ULL));
    return h;
}

/* Uniform in [0, 1) with 24 (float) or 53 (double) random bits. */
static inline float sk_u64_to_unit_f(uint64_t h) { return (float)(h >> 40) * 0x1.0p-24f; }
static inline double sk_u64_to_unit_d(uint64_t h) { return (double)(h >> 11) * 0x1.0p-53; }

/* A small counter-based stream, for an object that needs several random numbers: the
 * stream is keyed by (seed, ids) and its n-th value is hash(key, n). Copying or
 * re-creating the stream with the same key replays the same values. */
typedef struct sk_rng {
    uint64_t key;
    uint64_t counter;
} sk_rng;

static inline sk_rng sk_rng_make(uint64_t seed, uint64_t a, uint64_t b, uint64_t c)
{
    sk_rng r;
    r.key = sk_hash(seed, a, b, c);
    r.counter = 0;
    return r;
}
static inline uint64_t sk_rng_next_u64(sk_rng *r)
{
    return sk_mix64(r->key ^ sk_mix64(++r->counter * 0x9e3779b97f4a7c15ULL));
}
/* Uniform in [0, 1). */
static inline double sk_rng_uniform(sk_rng *r) { return sk_u64_to_unit_d(sk_rng_next_u64(r)); }
/* Uniform in [lo, hi). */
static inline double sk_rng_range(sk_rng *r, double lo, double hi)
{
    return lo + (hi - lo) * sk_rng_uniform(r);
}
/* Standard normal N(0, 1) by the Box-Muller transform (two uniforms per sample, so the
 * sample count never depends on a rejection loop). */
double sk_rng_normal(sk_rng *r);
/* Integer uniform in [0, n), n > 0 (multiply-shift, bias below 2^-32 for n < 2^32). */
static inline uint32_t sk_rng_below(sk_rng *r, uint32_t n)
{
    return (uint32_t)(((sk_rng_next_u64(r) >> 32) * (uint64_t)n) >> 32);
}

/* One-shot helpers: a single uniform / normal value for (seed, a, b, c). */
static inline double sk_rand_uniform(uint64_t seed, uint64_t a, uint64_t b, uint64_t c)
{
    return sk_u64_to_unit_d(sk_hash(seed, a, b, c));
}
double sk_rand_normal(uint64_t seed, uint64_t a, uint64_t b, uint64_t c);

/* Folds a signed integer (e.g. a lattice coordinate) into an id without collisions. */
static inline uint64_t sk_id_from_int(int64_t v) { return (uint64_t)v; }

/* --------------------------------------------------------------------- noise */
/* Seeded gradient noise (Perlin 1985/2002: quintic fade, hashed unit gradients) and
 * fractal Brownian motion. Continuous with continuous first derivatives.
 *
 * Range: sk_noise2 / sk_noise3 return values in [-1, 1] (the raw sum is scaled by the
 * bound of gradient noise with unit gradients, sqrt(N)/2, so the extreme +-1 is
 * reachable only in principle; in practice |n| < 0.9, with standard deviation about
 * 0.2-0.25). The value is 0 at every integer lattice point.
 * sk_fbm2 / sk_fbm3 divide by the sum of octave amplitudes, so they are in [-1, 1] too.
 *
 * Periodic variants wrap the lattice: sk_noise2_periodic(x + px, y) == sk_noise2_periodic(x, y)
 * for integer periods px, py >= 1 (tileable textures). */
float sk_noise2(uint64_t seed, float x, float y);
float sk_noise3(uint64_t seed, float x, float y, float z);
float sk_noise2_periodic(uint64_t seed, float x, float y, int period_x, int period_y);

/* Gradient noise with its analytic gradient (d/dx, d/dy[, d/dz]) written to grad. */
float sk_noise2_grad(uint64_t seed, float x, float y, float grad[2]);
float sk_noise3_grad(uint64_t seed, float x, float y, float z, float grad[3]);

typedef struct sk_fbm_desc {
    int octaves;      /* number of octaves; 0 = 5; range 1..16 */
    float lacunarity; /* frequency ratio between octaves; 0 = 2.0; range (1, 8] */
    float gain;       /* amplitude ratio between octaves (= 2^-H); 0 = 0.5; range (0, 1) */
} sk_fbm_desc;

/* Fills zero fields of `desc` with the defaults above. */
sk_fbm_desc sk_fbm_desc_resolved(const sk_fbm_desc *desc);
/* Checks a resolved fbm desc; `name` prefixes field names in the message. */
sk_result sk_fbm_desc_validate(const sk_fbm_desc *desc, const char *name, sk_error *err);

/* Fractal sum of octaves of sk_noise*, each octave with its own derived seed. The desc
 * should be resolved (sk_fbm_desc_resolved); out-of-range fields are clamped. */
float sk_fbm2(uint64_t seed, float x, float y, const sk_fbm_desc *desc);
float sk_fbm3(uint64_t seed, float x, float y, float z, const sk_fbm_desc *desc);
/* Tileable fBm: octave k has lattice period period * round(lacunarity^k); with the
 * default lacunarity 2 every octave tiles with the base period. */
float sk_fbm2_periodic(uint64_t seed, float x, float y, int period_x, int period_y,
                       const sk_fbm_desc *desc);

/* ------------------------------------------------------------------- threads */
/* Parallel loops use OpenMP. The library's results never depend on the thread count:
 * work items are independent, and reductions sum fixed chunks in a fixed order.
 * sk_threads_set caps the threads used by later parallel loops in this process (it
 * sets OpenMP's own setting; 0 restores the OpenMP default). */
void sk_threads_set(int count);
int sk_threads_max(void);
/* Inside a parallel loop: this thread's index in its team (0 .. team size - 1) and the
 * team's size; outside one (and in builds without threads): 0 and 1. Per-thread scratch
 * is indexed by these, so the library never calls the thread runtime directly. */
int sk_thread_index(void);
int sk_thread_team_size(void);
/* Lets the idle threads of the last parallel loops go now, so they do not spin beside
 * serial work that follows (e.g. one thread writing a file): on a loaded machine they
 * would take its core. Call between parallel phases, not inside a parallel loop. */
void sk_threads_rest(void);

/* ------------------------------------------------------------------ progress */
/* A progress sink the library calls during long work with the fraction done in
 * [0, 1]. Library loops call it only from one thread, at most a few hundred times. */
typedef void (*sk_progress_fn)(void *user, double fraction);
typedef struct sk_progress {
    sk_progress_fn fn; /* NULL: no progress reporting */
    void *user;
} sk_progress;

/* Reports `fraction` if a sink is set (NULL-safe). */
void sk_progress_report(const sk_progress *progress, double fraction);

/* A terminal progress bar on stderr with percent and ETA, redrawn at most 10 times a
 * second. It draws only if `enabled` is true and stderr is a terminal. */
typedef struct sk_progress_bar {
    char label[48];
    bool active;
    double start_seconds;
    double last_draw_seconds;
    int last_percent;
} sk_progress_bar;

void sk_progress_bar_begin(sk_progress_bar *bar, const char *label, bool enabled);
void sk_progress_bar_update(sk_progress_bar *bar, double fraction);
void sk_progress_bar_end(sk_progress_bar *bar);
/* An sk_progress that feeds a bar: sk_progress p = sk_progress_bar_sink(&bar); */
sk_progress sk_progress_bar_sink(sk_progress_bar *bar);

/* Monotonic wall clock in seconds (for progress ETAs and benchmarks). */
double sk_time_seconds(void);

#ifdef __cplusplus
}
#endif

#endif /* SHITSUKAN_CORE_H */
