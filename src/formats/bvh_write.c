/* BVH writing: the text
 * form of include/shitsukan/bvh.h (tabs, LF, 9 decimals, "C" locale), written atomically. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/io_internal.h"
#include "shitsukan/bvh.h"
#include "shitsukan/io.h"
#include "base/bvh_internal.h"

static void indent(FILE *out, int depth)
{
    for (int i = 0; i < depth; i++) fputc('\t', out);
}

static void write_joint(FILE *out, const sk_bvh *b, int j, int depth)
{
    static const char *const names[6] = {"Xposition", "Yposition", "Zposition",
                                         "Xrotation", "Yrotation", "Zrotation"};
    indent(out, depth);
    if (b->end_site[j])
        fputs("End Site\n", out);
    else
        fprintf(out, "%s %s\n", b->parent[j] < 0 ? "ROOT" : "JOINT", b->name[j]);
    indent(out, depth);
    fputs("{\n", out);
    indent(out, depth + 1);
    fprintf(out, "OFFSET %.9f %.9f %.9f\n", b->offset[j].x, b->offset[j].y, b->offset[j].z);
    if (!b->end_site[j]) {
        indent(out, depth + 1);
        fprintf(out, "CHANNELS %d", b->channel_count[j]);
        for (int c = 0; c < b->channel_count[j]; c++)
            fprintf(out, " %s", names[sk__bvh_channel_index(b->channel[j][c])]);
        fputc('\n', out);
    }
    for (int k = j + 1; k < b->joint_count; k++)
        if (b->parent[k] == j) write_joint(out, b, k, depth + 1);
    indent(out, depth);
    fputs("}\n", out);
}

sk_result sk_bvh_write_stream(const sk_bvh *b, FILE *out)
{
    sk__c_locale locale;
    sk__c_locale_push(&locale);
    fputs("HIERARCHY\n", out);
    for (int j = 0; j < b->joint_count; j++)
        if (b->parent[j] < 0) write_joint(out, b, j, 0);
    fputs("MOTION\n", out);
    fprintf(out, "Frames: %d\nFrame Time: %.9f\n", b->frame_count, b->frame_time);
    for (int f = 0; f < b->frame_count; f++) {
        const double *m = b->motion + (size_t)f * (size_t)b->channels_per_frame;
        for (int c = 0; c < b->channels_per_frame; c++) fprintf(out, c ? " %.9f" : "%.9f", m[c]);
        fputc('\n', out);
    }
    sk__c_locale_pop(&locale);
    return ferror(out) ? SK_ERROR_IO : SK_OK;
}

sk_result sk_bvh_write(const sk_bvh *b, const char *path, sk_error *err)
{
    if (b->joint_count < 1)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "a BVH needs at least one joint");
    if (b->frame_count < 1 || !b->motion)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "a BVH needs at least one frame of motion");
    if (!(b->frame_time > 0.0))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "frame time %g must be positive",
                       b->frame_time);
    size_t total = (size_t)b->frame_count * (size_t)b->channels_per_frame;
    for (size_t i = 0; i < total; i++)
        if (!isfinite(b->motion[i]))
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "motion value %zu (frame %zu) is not finite", i,
                           i / (size_t)b->channels_per_frame);
    sk_atomic_file file;
    sk_result r = sk_atomic_file_open(&file, path, err);
    if (r != SK_OK) return r;
    if (sk_bvh_write_stream(b, file.fp) != SK_OK) return sk_atomic_file_write_failed(&file, err);
    return sk_atomic_file_commit(&file, err);
}
