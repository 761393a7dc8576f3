/* Stick-figure frames of an animation (thesis 4.2.2-4.2.3): one layout fitted over every
 * frame so the frames line up, drawn and written in parallel as numbered PNG files. */
#define _POSIX_C_SOURCE 200809L
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/loop_progress.h"
#include "models/hand/hand_internal.h"
#include "shitsukan/hand.h"
#include "shitsukan/io.h"

sk_result sk_hand_frames_write_png(const sk_hand_skeleton *skeleton, const double *dofs,
                                   int frame_count, const sk_hand_draw_desc *desc,
                                   const char *const *captions, const char *dir,
                                   sk_progress progress, sk_error *err)
{
    if (!dir || !dir[0]) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "no folder for the frames");
    if (frame_count < 1 || frame_count > 10000000)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "frame_count = %d is out of range [1, 10000000]", frame_count);
    sk_hand_draw_desc d = sk_hand_draw_desc_resolved(desc);
    /* the caption band is sized for the longest caption */
    sk_hand_draw_desc fit = d;
    for (int f = 0; captions && f < frame_count; f++)
        if (captions[f] && (!fit.caption || strlen(captions[f]) > strlen(fit.caption)))
            fit.caption = captions[f];
    sk_hand_draw_layout layout;
    sk_result r = sk_hand_draw_layout_fit(skeleton, dofs, frame_count, &fit, &layout, err);
    if (r == SK_OK) r = sk_make_dirs(dir, err);
    if (r != SK_OK) return r;
    int digits = 4;
    for (int n = frame_count - 1; n >= 10000; n /= 10) digits++;

    sk__loop_progress lp;
    sk__loop_progress_init(&lp, &progress, frame_count);
    /* the error of the lowest failing frame is reported (the same whatever the threads) */
    int failed_frame = INT_MAX;
    sk_error first = {0};
    sk_result first_result = SK_OK;
#pragma omp parallel for schedule(dynamic, 1)
    for (int f = 0; f < frame_count; f++) {
        int seen;
#pragma omp atomic read
        seen = failed_frame;
        if (seen < f) continue;
        sk_hand_draw_desc fd = d;
        if (captions) fd.caption = captions[f];
        char path[PATH_MAX];
        sk_error e = {0};
        sk_image img = {0};
        sk_result fr = SK_OK;
        if (snprintf(path, sizeof path, "%s/frame_%0*d.png", dir, digits, f) >= (int)sizeof path)
            fr = sk_fail(&e, SK_ERROR_INVALID_ARGUMENT, "folder name too long: %s", dir);
        if (fr == SK_OK)
            fr = sk_hand_draw(skeleton, dofs + (size_t)f * SK_HAND_DOF_COUNT, &fd, &layout, &img,
                              &e);
        if (fr == SK_OK) fr = sk_image_write_png(&img, path, NULL, &e);
        sk_image_free(&img);
        if (fr != SK_OK) {
#pragma omp critical(sk_hand_frames_error)
            if (f < failed_frame) {
                failed_frame = f;
                first = e;
                first_result = fr;
            }
        }
        sk__loop_progress_tick(&lp);
    }
    if (first_result != SK_OK) {
        if (err) *err = first;
        sk_error_prefix(err, first_result, "frame %d", failed_frame);
        return first_result;
    }
    return SK_OK;
}
