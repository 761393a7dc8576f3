/* Animations of the glTF document (glTF 2.0 sec. 3.11): channels of node translation,
 * rotation, scale or morph weights, each with its own sampler of key times (seconds,
 * strictly increasing, >= 0) and values, LINEAR or STEP. Checked on the way in against
 * what the Khronos validator refuses: duplicate targets, weights on nodes without morph
 * targets, transforms of skinned-mesh nodes (ignored by glTF), non-unit quaternions. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "formats/gltf_internal.h"

void sk__gltf_animation_free(sk__gltf_animation *a)
{
    for (int c = 0; c < a->channel_count; c++) {
        free(a->channels[c].times);
        free(a->channels[c].values);
    }
    free(a->channels);
    free(a->name);
    memset(a, 0, sizeof *a);
}

sk_result sk_gltf_add_animation(sk_gltf *gltf, const char *name, int *out_index, sk_error *err)
{
    if (!gltf || !out_index)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "gltf or out_index is NULL");
    *out_index = SK_GLTF_NONE;
    int index = gltf->animation_count;
    sk_result r =
        sk__gltf_grow((void **)&gltf->animations, gltf->animation_count, &gltf->animation_capacity,
                      sizeof *gltf->animations, "animations", err);
    if (r != SK_OK) return r;
    sk__gltf_animation a = {0};
    if (!(a.name = sk__gltf_name(name, "animation", index)))
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    gltf->animations[index] = a;
    gltf->animation_count++;
    *out_index = index;
    return SK_OK;
}

static const char *path_name(sk_gltf_path path)
{
    static const char *const names[] = {"translation", "rotation", "scale", "weights"};
    return (unsigned)path < 4 ? names[path] : "?";
}

/* Values per key of a path on `node`, or a failure when the pairing is invalid. */
static sk_result path_components(const sk_gltf *gltf, int node, sk_gltf_path path, int *out,
                                 sk_error *err)
{
    const sk__gltf_node *n = &gltf->nodes[node];
    if (path == SK_GLTF_PATH_WEIGHTS) {
        if (n->mesh == SK_GLTF_NONE || gltf->meshes[n->mesh].target_count == 0)
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "path = weights needs a node with a mesh that has morph targets "
                           "(node = %d has none)",
                           node);
        *out = gltf->meshes[n->mesh].target_count;
        return SK_OK;
    }
    if (n->skin != SK_GLTF_NONE)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "node = %d carries a skinned mesh: glTF ignores its %s (animate the "
                       "joints)",
                       node, path_name(path));
    *out = path == SK_GLTF_PATH_ROTATION ? 4 : 3;
    return SK_OK;
}

static sk_result check_times(const float *times, int key_count, sk_error *err)
{
    for (int k = 0; k < key_count; k++) {
        if (!isfinite(times[k]) || times[k] < 0.0f)
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "times[%d] = %g: key times must be finite and >= 0", k,
                           (double)times[k]);
        if (k > 0 && !(times[k] > times[k - 1]))
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "times[%d] = %.9g is not after times[%d] = %.9g: key times must "
                           "increase strictly",
                           k, (double)times[k], k - 1, (double)times[k - 1]);
    }
    return SK_OK;
}

/* Copies the values, normalising rotations (refused when far from unit length). */
static sk_result copy_values(const float *values, int key_count, int components, sk_gltf_path path,
                             float *out, sk_error *err)
{
    size_t n = (size_t)key_count * (size_t)components;
    for (size_t i = 0; i < n; i++)
        if (!isfinite(values[i]))
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "values[%zu] (key %zu) is not finite", i,
                           i / (size_t)components);
    memcpy(out, values, n * sizeof(float));
    if (path != SK_GLTF_PATH_ROTATION) return SK_OK;
    for (int k = 0; k < key_count; k++) {
        float *q = out + 4 * k;
        double len = sqrt((double)q[0] * q[0] + (double)q[1] * q[1] + (double)q[2] * q[2] +
                          (double)q[3] * q[3]);
        if (!(fabs(len - 1.0) <= SK__GLTF_UNIT_TOLERANCE))
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "values of key %d: the rotation has length %.9g, must be 1", k, len);
        for (int c = 0; c < 4; c++) q[c] = (float)(q[c] / len);
    }
    return SK_OK;
}

static sk_result check_channel(const sk_gltf *gltf, const sk__gltf_animation *a, int node,
                               sk_gltf_path path, sk_gltf_interpolation interpolation,
                               const float *times, int key_count, const float *values,
                               int *components, sk_error *err)
{
    if (node < 0 || node >= gltf->node_count)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "node = %d is not a node of the document (%d nodes)", node,
                       gltf->node_count);
    if ((unsigned)path > SK_GLTF_PATH_WEIGHTS)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "path = %d is not a sk_gltf_path",
                       (int)path);
    if ((unsigned)interpolation > SK_GLTF_INTERPOLATION_STEP)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "interpolation = %d is not a sk_gltf_interpolation", (int)interpolation);
    for (int c = 0; c < a->channel_count; c++)
        if (a->channels[c].node == node && a->channels[c].path == path)
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "node = %d, path = %s is already animated by channel %d", node,
                           path_name(path), c);
    sk_result r = path_components(gltf, node, path, components, err);
    if (r != SK_OK) return r;
    if (key_count < 1 || key_count > SK__GLTF_MAX_OBJECTS || !times || !values)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "key_count = %d is out of range [1, %d] (or times / values is NULL)",
                       key_count, SK__GLTF_MAX_OBJECTS);
    return check_times(times, key_count, err);
}

sk_result sk_gltf_add_channel(sk_gltf *gltf, int animation, int node, sk_gltf_path path,
                              sk_gltf_interpolation interpolation, const float *times,
                              int key_count, const float *values, sk_error *err)
{
    if (!gltf) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "gltf is NULL");
    if (animation < 0 || animation >= gltf->animation_count)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "animation = %d is not an animation of the document (%d animations)",
                       animation, gltf->animation_count);
    sk__gltf_animation *a = &gltf->animations[animation];
    int index = a->channel_count, components = 0;
    sk_result r = check_channel(gltf, a, node, path, interpolation, times, key_count, values,
                                &components, err);
    if (r != SK_OK) return sk_error_prefix(err, r, "animations[%d].channels[%d]", animation, index);
    r = sk__gltf_grow((void **)&a->channels, a->channel_count, &a->channel_capacity,
                      sizeof *a->channels, "channels", err);
    if (r != SK_OK) return r;
    sk__gltf_channel c = {0};
    c.node = node;
    c.path = path;
    c.interpolation = interpolation == SK_GLTF_INTERPOLATION_STEP ? SK_GLTF_INTERPOLATION_STEP
                                                                  : SK_GLTF_INTERPOLATION_LINEAR;
    c.key_count = key_count;
    c.components = components;
    c.times = malloc((size_t)key_count * sizeof(float));
    c.values = malloc((size_t)key_count * (size_t)components * sizeof(float));
    if (!c.times || !c.values) {
        r = sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for %d keys", key_count);
    } else {
        memcpy(c.times, times, (size_t)key_count * sizeof(float));
        r = copy_values(values, key_count, components, path, c.values, err);
    }
    if (r != SK_OK) {
        free(c.times);
        free(c.values);
        return sk_error_prefix(err, r, "animations[%d].channels[%d]", animation, index);
    }
    a->channels[index] = c;
    a->channel_count++;
    return SK_OK;
}
