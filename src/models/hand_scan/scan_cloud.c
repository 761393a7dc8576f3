/* The registered point cloud of thesis 4.1.1: the samples of both scans above the table
 * threshold ("Z 座標に閾値を設け測定テーブルなどの背景データを取り除いた後"), off the marker
 * bumps, in the hand's frame; or a user's point cloud taken as that data. */
#include <stdlib.h>
#include <string.h>

#include "models/hand_scan/scan_internal.h"

static sk_result grow(sk_hand_cloud *c, size_t count, bool with_truth, sk_error *err)
{
    sk_vec3d *p = realloc(c->position, sizeof *p * (count ? count : 1));
    if (p) c->position = p;
    uint8_t *s = realloc(c->side, count ? count : 1);
    if (s) c->side = s;
    sk_vec3d *t = NULL;
    if (with_truth) {
        t = realloc(c->true_position, sizeof *t * (count ? count : 1));
        if (t) c->true_position = t;
    }
    if (!p || !s || (with_truth && !t))
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "point cloud of %zu points", count);
    return SK_OK;
}

sk_result sk_hand_cloud_alloc(sk_hand_cloud *cloud, size_t count, bool with_truth, sk_error *err)
{
    memset(cloud, 0, sizeof *cloud);
    sk_result r = grow(cloud, count, with_truth, err);
    if (r != SK_OK) {
        sk_hand_cloud_free(cloud);
        return r;
    }
    cloud->count = count;
    return SK_OK;
}

void sk_hand_cloud_free(sk_hand_cloud *cloud)
{
    free(cloud->position);
    free(cloud->true_position);
    free(cloud->side);
    memset(cloud, 0, sizeof *cloud);
}

static bool on_marker(const sk_hand_range_scan *scan, const sk_hand_markers *m, sk_vec3d p)
{
    if (!m) return false;
    double keep_out = m->radius_mm + 0.5;
    for (int k = 0; k < m->count; k++)
        if (sk__dist2(p, sk_hand_rigid_apply(&scan->placement, m->centre[k])) < keep_out * keep_out)
            return true;
    return false;
}

sk_result sk_hand_cloud_append_scan(sk_hand_cloud *cloud, const sk_hand_range_scan *scan,
                                    const sk_hand_markers *markers, const sk_hand_rigid *to_hand,
                                    const sk_hand_rigid *truth_to_hand, sk_error *err)
{
    bool with_truth = cloud->count == 0 || cloud->true_position;
    size_t extra = 0;
    size_t n = (size_t)scan->lines * (size_t)scan->points;
    for (size_t k = 0; k < n; k++)
        extra += isfinite(scan->depth[k]) && scan->depth[k] >= scan->table_threshold_mm;
    sk_result r = grow(cloud, cloud->count + extra, with_truth, err);
    if (r != SK_OK) return r;
    const sk_hand_rigid *truth = truth_to_hand ? truth_to_hand : to_hand;
    size_t out = cloud->count;
    for (int i = 0; i < scan->lines; i++)
        for (int j = 0; j < scan->points; j++) {
            size_t k = (size_t)i * (size_t)scan->points + (size_t)j;
            float z = scan->depth[k];
            if (!isfinite(z) || z < scan->table_threshold_mm) continue;
            sk_vec3d p = sk_hand_range_scan_point(scan, i, j, z);
            if (on_marker(scan, markers, p)) continue;
            cloud->position[out] = sk_hand_rigid_apply(to_hand, p);
            if (with_truth)
                cloud->true_position[out] = sk_hand_rigid_apply(
                    truth, sk_hand_range_scan_point(scan, i, j, scan->true_depth[k]));
            cloud->side[out] = (uint8_t)scan->side;
            out++;
        }
    cloud->count = out;
    return SK_OK;
}

sk_result sk_hand_cloud_from_points(sk_hand_cloud *cloud, const sk_mesh *points,
                                    const sk_hand_frames *frames, sk_error *err)
{
    memset(cloud, 0, sizeof *cloud);
    if (points->vertex_count == 0)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "the point cloud is empty");
    if (points->vertex_count > (1u << 26))
        return sk_fail(err, SK_ERROR_LIMIT, "the point cloud has %zu points (at most 2^26)",
                       points->vertex_count);
    sk_result r = sk_hand_cloud_alloc(cloud, points->vertex_count, false, err);
    if (r != SK_OK) return r;
    sk_hand_link_geometry links;
    sk_hand_link_geometry_from_frames(frames, &links);
    sk_vec3d palmar = {frames->rotation[0].m[0][2], frames->rotation[0].m[1][2],
                       frames->rotation[0].m[2][2]};
    /* a cloud written by sk_hand_cloud_write_ply says its sides */
    const sk_mesh_attribute *given = sk_mesh_find_attribute(points, "side");
    if (given && given->components != 1) given = NULL;
    for (size_t i = 0; i < points->vertex_count; i++) {
        const float *q = points->positions + 3 * i;
        sk_vec3d p = sk_v3d(q[0], q[1], q[2]);
        cloud->position[i] = p;
        double toward;
        if (given) {
            toward = given->data[i] < 0.5f ? 1.0 : -1.0;
        } else if (points->normals) {
            const float *n = points->normals + 3 * i;
            toward = sk_v3d_dot(sk_v3d(n[0], n[1], n[2]), palmar);
        } else {
            /* which side of its link's axis, seen along the palm's normal */
            int l = sk_hand_nearest_link(&links, p, NULL);
            sk_vec3d ab = sk_v3d_sub(links.b[l], links.a[l]);
            double len2 = sk_v3d_dot(ab, ab);
            double t = len2 > 0 ? sk_v3d_dot(sk_v3d_sub(p, links.a[l]), ab) / len2 : 0.0;
            t = t < 0 ? 0 : (t > 1 ? 1 : t);
            toward = sk_v3d_dot(sk_v3d_sub(p, sk_v3d_add(links.a[l], sk_v3d_scale(ab, t))), palmar);
        }
        cloud->side[i] = (uint8_t)(toward >= 0.0 ? SK_HAND_SCAN_PALM : SK_HAND_SCAN_BACK);
    }
    return SK_OK;
}
