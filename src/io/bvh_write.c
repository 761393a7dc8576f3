/* BVH building and writing: a skeleton assembled joint by joint, its motion, and the text
 * form of include/shitsukan/bvh.h (tabs, LF, 9 decimals, "C" locale), written atomically. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io/io_internal.h"
#include "shitsukan/bvh.h"
#include "shitsukan/io.h"

void sk_bvh_init(sk_bvh *b) { memset(b, 0, sizeof *b); }

static int channel_code_index(char c)
{
    static const char codes[6] = {'x', 'y', 'z', 'X', 'Y', 'Z'};
    for (int i = 0; i < 6; i++)
        if (codes[i] == c) return i;
    return -1;
}

sk_result sk_bvh_add_joint(sk_bvh *b, const char *name, int parent, sk_vec3d offset,
                           const char *channels, bool end_site, int *out_index, sk_error *err)
{
    if (b->motion)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "joints must be added before the motion");
    if (b->joint_count >= SK_BVH_MAX_JOINTS)
        return sk_fail(err, SK_ERROR_LIMIT, "more than %d joints and end sites", SK_BVH_MAX_JOINTS);
    if (!name || !name[0] || strlen(name) >= SK_BVH_NAME_SIZE || strpbrk(name, " \t\r\n{}"))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "joint name \"%s\" must be 1-%d bytes without white space or braces",
                       name ? name : "(null)", SK_BVH_NAME_SIZE - 1);
    if (parent < -1 || parent >= b->joint_count || (parent >= 0 && b->end_site[parent]))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "joint \"%s\": parent %d is not a joint added before", name, parent);
    if (end_site && parent < 0)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "end site \"%s\" needs a parent", name);
    size_t n = channels ? strlen(channels) : 0;
    if (n > 6 || (end_site && n > 0))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "joint \"%s\": %s", name,
                       end_site ? "an end site has no channels" : "more than 6 channels");
    for (size_t i = 0; i < n; i++)
        if (channel_code_index(channels[i]) < 0 || memchr(channels, channels[i], i))
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "joint \"%s\": channels \"%s\" must be distinct codes of xyzXYZ", name,
                           channels);
    if (!isfinite(offset.x) || !isfinite(offset.y) || !isfinite(offset.z))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "joint \"%s\": offset is not finite", name);
    int j = b->joint_count++;
    snprintf(b->name[j], sizeof b->name[j], "%s", name);
    b->parent[j] = parent;
    b->end_site[j] = end_site;
    b->offset[j] = offset;
    b->channel_count[j] = (int)n;
    b->channel_first[j] = b->channels_per_frame;
    if (n) memcpy(b->channel[j], channels, n);
    b->channels_per_frame += (int)n;
    if (out_index) *out_index = j;
    return SK_OK;
}

sk_result sk_bvh_alloc_motion(sk_bvh *b, int frame_count, double frame_time, sk_error *err)
{
    if (frame_count < 1)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "frame count %d must be at least 1",
                       frame_count);
    if (!(frame_time > 0.0) || !isfinite(frame_time))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "frame time %g must be positive",
                       frame_time);
    size_t total;
    if (!sk_size_mul((size_t)frame_count,
                     (size_t)(b->channels_per_frame ? b->channels_per_frame : 1), &total) ||
        total > ((size_t)1 << 30))
        return sk_fail(err, SK_ERROR_LIMIT, "%d frames x %d channels is too much motion",
                       frame_count, b->channels_per_frame);
    free(b->motion);
    b->motion = calloc(total, sizeof *b->motion);
    if (!b->motion) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    b->frame_count = frame_count;
    b->frame_time = frame_time;
    return SK_OK;
}

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
            fprintf(out, " %s", names[channel_code_index(b->channel[j][c])]);
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
