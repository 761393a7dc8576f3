/* The BVH skeleton and motion in memory: building one joint by joint, lookup, local and
 * global poses (files are read by src/formats/bvh_read.c, written by bvh_write.c). */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include "base/io_internal.h"
#include "shitsukan/bvh.h"
#include "base/bvh_internal.h"

void sk_bvh_init(sk_bvh *b) { memset(b, 0, sizeof *b); }

int sk__bvh_channel_index(char c)
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
        if (sk__bvh_channel_index(channels[i]) < 0 || memchr(channels, channels[i], i))
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

void sk_bvh_free(sk_bvh *b)
{
    if (!b) return;
    free(b->motion);
    b->motion = NULL;
    b->frame_count = 0;
}

int sk_bvh_find(const sk_bvh *b, const char *name)
{
    for (int j = 0; j < b->joint_count; j++)
        if (strcmp(b->name[j], name) == 0) return j;
    return -1;
}

void sk_bvh_local(const sk_bvh *b, int j, int frame, sk_mat3d *rotation, sk_vec3d *translation)
{
    const double *m = b->motion ? b->motion + (size_t)frame * (size_t)b->channels_per_frame : NULL;
    sk_vec3d t = b->offset[j];
    sk_mat3d r = sk_m3d_identity();
    for (int c = 0; m && c < b->channel_count[j]; c++) {
        double v = m[b->channel_first[j] + c];
        switch (b->channel[j][c]) {
        case 'x':
            t.x += v;
            break;
        case 'y':
            t.y += v;
            break;
        case 'z':
            t.z += v;
            break;
        case 'X':
            r = sk_m3d_mul(r, sk_m3d_rot_x(v * SK_DEG_TO_RAD));
            break;
        case 'Y':
            r = sk_m3d_mul(r, sk_m3d_rot_y(v * SK_DEG_TO_RAD));
            break;
        default:
            r = sk_m3d_mul(r, sk_m3d_rot_z(v * SK_DEG_TO_RAD));
            break;
        }
    }
    if (rotation) *rotation = r;
    if (translation) *translation = t;
}

void sk_bvh_pose(const sk_bvh *b, int frame, sk_mat3d *rotations, sk_vec3d *positions)
{
    sk_mat3d g[SK_BVH_MAX_JOINTS];
    for (int j = 0; j < b->joint_count; j++) {
        sk_mat3d r;
        sk_vec3d t;
        sk_bvh_local(b, j, frame, &r, &t);
        int p = b->parent[j];
        if (p < 0) {
            g[j] = r;
            positions[j] = t;
        } else {
            g[j] = sk_m3d_mul(g[p], r);
            positions[j] = sk_v3d_add(positions[p], sk_m3d_apply(g[p], t));
        }
        if (rotations) rotations[j] = g[j];
    }
}

void sk_bvh_positions(const sk_bvh *b, int frame, sk_vec3d *out)
{
    sk_bvh_pose(b, frame, NULL, out);
}
