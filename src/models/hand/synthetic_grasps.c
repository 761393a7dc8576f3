/* Synthetic glove-like recordings of finger flexion for calibrating and evaluating the
 * natural-posture potential (thesis 3.2.2 measures joint angles of real hands; no real
 * recording can be shipped): people grasp ten object types in trials of reach, hold and
 * release, with the couplings reported for real glove data (neighbouring PIPs strongly
 * coupled, neighbouring MCPs moderately, MCP and PIP of one finger weakly, DIP a curved
 * function of PIP) and the hand opening beyond the grasp on the way to an object
 * (pre-shaping, Jeannerod 1984). */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "models/hand/hand_internal.h"

#define FINGERS 4
#define GRASPS 10

/* Grasp postures (degrees): MCP and PIP flexion of index, middle, ring, little. */
static const struct {
    const char *name;
    double mcp[FINGERS], pip[FINGERS];
    bool object; /* an object is grasped: the hand opens beyond it on the way (pre-shaping) */
} GRASP[GRASPS] = {
    {"relaxed", {20, 25, 30, 35}, {25, 30, 35, 40}, false},
    {"flat hand on a table", {2, 0, 0, 3}, {4, 3, 4, 6}, false},
    {"cylinder (bottle)", {55, 58, 60, 62}, {75, 80, 80, 78}, true},
    {"sphere (ball)", {38, 40, 42, 45}, {45, 50, 52, 55}, true},
    {"pinch (coin)", {45, 35, 35, 38}, {40, 45, 50, 55}, true},
    {"tripod (pen)", {40, 45, 60, 65}, {45, 50, 85, 90}, true},
    {"pointing", {5, 55, 60, 65}, {8, 95, 100, 100}, false},
    {"hook (bag handle)", {10, 10, 12, 15}, {85, 90, 90, 88}, true},
    {"plate (flat object, fingers straight)", {70, 72, 74, 75}, {5, 5, 6, 8}, true},
    {"fist", {70, 72, 75, 78}, {95, 100, 100, 98}, false},
};

/* The DIP follows its PIP along a curve: nothing below about 20 degrees, then about
 * 0.7 of the PIP's further flexion (a smooth hinge), times the person's gain. */
static double dip_of_pip(double pip, double gain)
{
    double u = (pip - 20.0) / 6.0;
    double hinge = u > 30 ? u : log1p(exp(u));
    return gain * 0.7 * 6.0 * hinge;
}

static double smoothstep(double t)
{
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    return t * t * (3 - 2 * t);
}

/* 0 at u = 0 and u = 1, 1 at u = peak, smooth. */
static double bump(double u, double peak)
{
    return u < peak ? smoothstep(u / peak) : smoothstep((1.0 - u) / (1.0 - peak));
}

typedef struct text_buffer {
    char *data;
    size_t length, capacity;
    bool failed;
} text_buffer;

static void append(text_buffer *b, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

static void append(text_buffer *b, const char *fmt, ...)
{
    if (b->failed) return;
    for (;;) {
        va_list args;
        va_start(args, fmt);
        int n = vsnprintf(b->data + b->length, b->capacity - b->length, fmt, args);
        va_end(args);
        if (n < 0) {
            b->failed = true;
            return;
        }
        if ((size_t)n < b->capacity - b->length) {
            b->length += (size_t)n;
            return;
        }
        size_t cap = b->capacity * 2 + (size_t)n + 1024;
        char *grown = realloc(b->data, cap);
        if (!grown) {
            b->failed = true;
            return;
        }
        b->data = grown;
        b->capacity = cap;
    }
}

sk_result sk_hand_synthetic_grasps_csv(const sk_hand_synthetic_desc *desc, char **text,
                                       size_t *length, sk_error *err)
{
    *text = NULL;
    *length = 0;
    sk_hand_synthetic_desc d = {0};
    if (desc) d = *desc;
    sk_schema_apply_defaults(&sk_hand_synthetic_schema, &d);
    if (d.noise_deg < 0.0) d.noise_deg = 0.0;
    sk_result r = sk_schema_check(&sk_hand_synthetic_schema, &d, "", err);
    if (r != SK_OK) return r;
    sk_hand_anatomy anatomy;
    sk_hand_anatomy_default(&anatomy);
    static const char *const finger_name[FINGERS] = {"I", "M", "R", "L"};
    static const char *const joint_name[3] = {"MCP", "PIP", "DIP"};
    int dof[FINGERS][3];
    for (int f = 0; f < FINGERS; f++)
        for (int j = 0; j < 3; j++) {
            char name[16];
            snprintf(name, sizeof name, "%s.%s.flex", finger_name[f], joint_name[j]);
            dof[f][j] = sk_hand_dof_find(name);
        }
    text_buffer b = {malloc(1 << 16), 0, 1 << 16, false};
    if (!b.data) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    append(
        &b,
        "# Synthetic glove recordings of finger flexion, made by shitsukan "
        "(sk_hand_synthetic_grasps_csv,\n"
        "# `shitsukan hand synthesize`: seed %llu, %d people x %d grasp types x %d trials x %d "
        "frames).\n"
        "# Not a measurement: it stands in for real recordings, with the couplings reported for "
        "real\n"
        "# glove data. Each trial reaches from the person's relaxed posture to a grasp, holds it "
        "and\n"
        "# releases. A grasp type fixes MCP and PIP flexion per finger; per trial an aperture "
        "moves the\n"
        "# PIPs of all fingers together (sd 10 deg; each PIP also 5 on its own) and each MCP by sd "
        "10\n"
        "# deg, partly shared with its radial neighbour (r = 0.5 index-middle, 0.7 middle-ring, "
        "0.8\n"
        "# ring-little), so neighbouring PIPs are strongly coupled, neighbouring MCPs moderately "
        "and\n"
        "# the MCP and PIP of one finger weakly. On the way to an object and off it the hand "
        "opens\n"
        "# beyond the grasp (pre-shaping: up to 15 deg MCP and 25 deg PIP extension, x 0.7-1.3 "
        "per\n"
        "# trial, widest at 65 %% of the reach and 35 %% of the release). The DIP follows its PIP\n"
        "# along a hinge (none below 20 deg of PIP, then 0.7 of the rest) times a personal gain "
        "of\n"
        "# 0.45-1. People differ by an offset (sd 5 deg) and a range (x 0.85-1.15); every trial "
        "has a\n"
        "# glove calibration offset (sd 2 deg) and every sample glove noise (sd %.3g deg); angles "
        "are\n"
        "# clamped to the joint limits. Grasp types:",
        (unsigned long long)d.seed, d.people, GRASPS, d.trials, d.frames, d.noise_deg);
    for (int g = 0; g < GRASPS; g++) append(&b, "%s %s", g ? "," : "", GRASP[g].name);
    append(&b, ".\nperson,trial,frame");
    for (int f = 0; f < FINGERS; f++)
        for (int j = 0; j < 3; j++) append(&b, ",%s", sk_hand_dof(dof[f][j])->name);
    append(&b, "\n");
    for (int p = 0; p < d.people && !b.failed; p++) {
        sk_rng pr = sk_rng_make(d.seed, 0x706572, (uint64_t)p, 0);
        double offset[FINGERS][3], range = sk_rng_range(&pr, 0.85, 1.15),
                                   gain = sk_rng_range(&pr, 0.45, 1.0);
        for (int f = 0; f < FINGERS; f++)
            for (int j = 0; j < 3; j++) offset[f][j] = 5.0 * sk_rng_normal(&pr);
        for (int g = 0; g < GRASPS; g++)
            for (int t = 0; t < d.trials; t++) {
                sk_rng tr = sk_rng_make(d.seed, 0x747269, (uint64_t)p, (uint64_t)(g * 1000 + t));
                double aperture = sk_rng_normal(&tr), calib[FINGERS][3], mcp_own[FINGERS],
                       pip_own[FINGERS];
                /* each MCP's own variation shares part of its radial neighbour's */
                static const double NEIGHBOUR_R[FINGERS] = {0.0, 0.5, 0.7, 0.8};
                double z = 0.0;
                for (int f = 0; f < FINGERS; f++) {
                    z = NEIGHBOUR_R[f] * z +
                        sqrt(1.0 - NEIGHBOUR_R[f] * NEIGHBOUR_R[f]) * sk_rng_normal(&tr);
                    mcp_own[f] = 10.0 * z;
                    pip_own[f] = 5.0 * sk_rng_normal(&tr);
                    for (int j = 0; j < 3; j++) calib[f][j] = 2.0 * sk_rng_normal(&tr);
                }
                double tremor_phase = sk_rng_range(&tr, 0, 2 * SK_PI);
                double opening = GRASP[g].object ? sk_rng_range(&tr, 0.7, 1.3) : 0.0;
                for (int k = 0; k < d.frames; k++) {
                    double s = (double)k / (d.frames - 1);
                    /* reach (first 30 %), hold, release (last 30 %); on the way to an object and
                       off it the hand opens beyond the grasp (widest at 65 % of the reach and
                       35 % of the release) */
                    double w = s < 0.3   ? smoothstep(s / 0.3)
                               : s > 0.7 ? smoothstep((1.0 - s) / 0.3)
                                         : 1.0;
                    double open = opening * (s < 0.3   ? bump(s / 0.3, 0.65)
                                             : s > 0.7 ? bump((s - 0.7) / 0.3, 0.35)
                                                       : 0.0);
                    double drift = sin(tremor_phase + 9.0 * s);
                    append(&b, "p%d,p%d-g%d-t%d,%d", p + 1, p + 1, g + 1, t + 1, k);
                    sk_rng nr = sk_rng_make(d.seed, 0x6e6f69, (uint64_t)p,
                                            (uint64_t)((g * 1000 + t) * 10000 + k));
                    for (int f = 0; f < FINGERS; f++) {
                        double mcp_rest = GRASP[0].mcp[f], pip_rest = GRASP[0].pip[f];
                        double mcp_g = GRASP[g].mcp[f] + mcp_own[f] + 1.0 * drift;
                        double pip_g = GRASP[g].pip[f] + 10.0 * aperture + pip_own[f] + 1.5 * drift;
                        double mcp = range * (mcp_rest + w * (mcp_g - mcp_rest)) + offset[f][0] -
                                     15.0 * open;
                        double pip = range * (pip_rest + w * (pip_g - pip_rest)) + offset[f][1] -
                                     25.0 * open;
                        double dip = dip_of_pip(pip, gain) + offset[f][2];
                        double v[3] = {mcp, pip, dip};
                        for (int j = 0; j < 3; j++) {
                            const sk_hand_dof_data *dd = &anatomy.dof[dof[f][j]];
                            double x = v[j] + calib[f][j] + d.noise_deg * sk_rng_normal(&nr);
                            x = sk_clampd(x, dd->min * SK_RAD_TO_DEG, dd->max * SK_RAD_TO_DEG);
                            append(&b, ",%.2f", x);
                        }
                    }
                    append(&b, "\n");
                }
            }
    }
    if (b.failed) {
        free(b.data);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    }
    *text = b.data;
    *length = b.length;
    return SK_OK;
}
