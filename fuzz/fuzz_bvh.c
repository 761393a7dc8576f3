/* Fuzz harness: the BVH reader (include/shitsukan/bvh.h). A parsed file must be well
 * formed (parents before children, channel offsets consistent, finite motion), pose at
 * its first and last frames, and write back to text that reads as the same skeleton. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "shitsukan/bvh.h"

static void check(const sk_bvh *b)
{
    int channels = 0;
    if (b->joint_count < 1 || b->joint_count > SK_BVH_MAX_JOINTS || !b->motion ||
        !(b->frame_time > 0))
        abort();
    for (int j = 0; j < b->joint_count; j++) {
        if (b->parent[j] >= j || b->parent[j] < -1) abort();
        if (b->channel_first[j] != channels || b->channel_count[j] < 0 || b->channel_count[j] > 6)
            abort();
        if (b->end_site[j] && b->channel_count[j]) abort();
        channels += b->channel_count[j];
    }
    if (channels != b->channels_per_frame) abort();
    for (size_t i = 0; i < (size_t)b->frame_count * (size_t)b->channels_per_frame; i++)
        if (!isfinite(b->motion[i])) abort();
}

static void round_trip(const sk_bvh *b)
{
    char *text = NULL;
    size_t size = 0;
    FILE *out = open_memstream(&text, &size);
    if (!out) return;
    sk_result r = sk_bvh_write_stream(b, out);
    fclose(out);
    sk_bvh *again = malloc(sizeof *again);
    if (r == SK_OK && again && b->frame_count > 0) {
        if (sk_bvh_parse(text, size, "round trip", again, NULL) != SK_OK) abort();
        if (again->joint_count != b->joint_count || again->frame_count != b->frame_count ||
            again->channels_per_frame != b->channels_per_frame)
            abort();
        for (int j = 0; j < b->joint_count; j++)
            if (strcmp(again->name[j], b->name[j]) != 0 || again->parent[j] != b->parent[j])
                abort();
        sk_bvh_free(again);
    }
    free(again);
    free(text);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    sk_bvh *b = malloc(sizeof *b);
    sk_vec3d *pos = malloc(sizeof(sk_vec3d) * SK_BVH_MAX_JOINTS);
    sk_mat3d *rot = malloc(sizeof(sk_mat3d) * SK_BVH_MAX_JOINTS);
    if (!b || !pos || !rot) abort();
    if (sk_bvh_parse((const char *)data, size, "fuzz", b, NULL) == SK_OK) {
        check(b);
        if (b->frame_count > 0) {
            sk_bvh_pose(b, 0, rot, pos);
            sk_bvh_positions(b, b->frame_count - 1, pos);
        }
        round_trip(b);
        sk_bvh_free(b);
    } else if (b->motion) {
        abort();
    }
    free(rot);
    free(pos);
    free(b);
    return 0;
}
