/* The skin's motion as glTF 2.0 (through include/shitsukan/gltf.h): the rest skin as a
 * mesh whose morph targets are the frames (position and normal displacements from rest),
 * and an animation of the morph weights, one target full on at each frame's time and
 * linear between (so a viewer shows the frames and blends them in between). Millimetres
 * are scaled to glTF's metres by the root node. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "shitsukan/gltf.h"
#include "models/tissue/tissue_internal.h"

sk_result sk__write_skin_glb(const sk_mesh *rest, const float *positions, const float *normals,
                             int frames, int first_frame, int fps, const char *path, sk_error *err)
{
    size_t n = rest->vertex_count, per = 3 * n;
    float *dp = malloc((size_t)frames * per * sizeof *dp),
          *dn = malloc((size_t)frames * per * sizeof *dn);
    float *times = malloc((size_t)frames * sizeof *times),
          *weights = calloc((size_t)frames * (size_t)frames, sizeof *weights);
    char(*names)[24] = malloc((size_t)frames * sizeof *names);
    const char **name_ptr = malloc((size_t)frames * sizeof *name_ptr);
    sk_gltf *g = NULL;
    sk_result r = SK_OK;
    if (!dp || !dn || !times || !weights || !names || !name_ptr)
        r = sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for %d frames of glTF", frames);
    for (int f = 0; r == SK_OK && f < frames; f++) {
        const float *p = positions + (size_t)f * per, *q = normals + (size_t)f * per;
        for (size_t i = 0; i < per; i++) {
            dp[(size_t)f * per + i] = p[i] - rest->positions[i];
            dn[(size_t)f * per + i] = q[i] - rest->normals[i];
        }
        times[f] = (float)((double)f / fps);
        weights[(size_t)f * (size_t)frames + (size_t)f] = 1.0f;
        snprintf(names[f], sizeof names[f], "frame%04d", first_frame + f);
        name_ptr[f] = names[f];
    }
    int material = 0, mesh = 0, root = 0, node = 0, animation = 0;
    if (r == SK_OK) r = sk_gltf_create(&g, err);
    if (r == SK_OK) {
        sk_gltf_material_desc md = {0};
        md.name = "skin";
        md.base_color[0] = 0.80f;
        md.base_color[1] = 0.56f;
        md.base_color[2] = 0.46f;
        md.base_color[3] = 1.0f;
        md.roughness = 0.6f;
        r = sk_gltf_add_material(g, &md, &material, err);
    }
    if (r == SK_OK) {
        sk_gltf_mesh_desc d = {0};
        d.name = "skin";
        d.mesh = rest;
        d.material = material;
        d.target_count = frames;
        d.target_positions = dp;
        d.target_normals = dn;
        d.target_names = name_ptr;
        r = sk_gltf_add_mesh(g, &d, &mesh, err);
    }
    if (r == SK_OK) {
        sk_gltf_node_desc nd = sk_gltf_node_desc_default();
        nd.name = "tissue";
        nd.scale[0] = nd.scale[1] = nd.scale[2] = 0.001; /* mm -> m */
        r = sk_gltf_add_node(g, &nd, &root, err);
    }
    if (r == SK_OK) {
        sk_gltf_node_desc nd = sk_gltf_node_desc_default();
        nd.name = "skin";
        nd.parent = root;
        nd.mesh = mesh;
        r = sk_gltf_add_node(g, &nd, &node, err);
    }
    if (r == SK_OK && frames > 1) r = sk_gltf_add_animation(g, "jiggle", &animation, err);
    if (r == SK_OK && frames > 1)
        r = sk_gltf_add_channel(g, animation, node, SK_GLTF_PATH_WEIGHTS,
                                SK_GLTF_INTERPOLATION_LINEAR, times, frames, weights, err);
    if (r == SK_OK) r = sk_gltf_write_glb(g, path, NULL, err);
    sk_gltf_destroy(g);
    free(dp);
    free(dn);
    free(times);
    free(weights);
    free(names);
    free(name_ptr);
    return r;
}
