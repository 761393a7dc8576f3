/* Cameras: a pinhole with look-at and vertical field of view, and an orthographic camera
 * for texture-like views; the all-zero camera frames the scene's bounding sphere. */
#include <math.h>

#include "render/render_internal.h"

/* Looks along -z at the scene's bounding sphere so that it fills the view. */
static void frame_scene(sk_render_scene *scene)
{
    sk_render_camera_desc *c = &scene->desc.camera;
    sk_vec3f centre = sk_v3f(0, 0, 0);
    float radius = 1.0f;
    if (scene->has_bounds) {
        centre = sk_v3f_scale(sk_v3f_add(scene->lo, scene->hi), 0.5f);
        radius = 0.5f * sk_v3f_length(sk_v3f_sub(scene->hi, scene->lo));
        if (!(radius > 0)) radius = 1.0f;
    }
    float aspect = (float)scene->desc.image.width / (float)scene->desc.image.height;
    float half = c->fov / 2;
    if (aspect < 1.0f) half = atanf(tanf(half) * aspect); /* the narrower horizontal fov */
    float distance = radius / sinf(half);
    if (c->projection == SK_RENDER_PROJECTION_ORTHOGRAPHIC) {
        distance = 2.0f * radius + 1.0f;
        if (c->ortho_height == 0) c->ortho_height = 2.0f * radius / (aspect < 1.0f ? aspect : 1.0f);
    }
    c->target[0] = centre.x, c->target[1] = centre.y, c->target[2] = centre.z;
    c->position[0] = centre.x, c->position[1] = centre.y, c->position[2] = centre.z + distance;
}

void sk__camera_setup(sk_render_scene *scene)
{
    sk_render_camera_desc *c = &scene->desc.camera;
    if (sk__v3f_is_zero(c->position) && sk__v3f_is_zero(c->target)) frame_scene(scene);
    sk__camera *cam = &scene->camera;
    float width = (float)scene->desc.image.width, height = (float)scene->desc.image.height;
    cam->projection = c->projection;
    cam->position = sk_v3f_load(c->position);
    sk_vec3f view = sk_v3f_sub(sk_v3f_load(c->target), cam->position);
    cam->forward = sk_v3f_normalize(view);
    cam->right = sk_v3f_normalize(sk_v3f_cross(cam->forward, sk_v3f_load(c->up)));
    cam->up = sk_v3f_cross(cam->right, cam->forward);
    cam->width = width;
    cam->height = height;
    float tan_half = tanf(c->fov / 2);
    if (c->projection == SK_RENDER_PROJECTION_ORTHOGRAPHIC) {
        if (c->ortho_height == 0) c->ortho_height = 2.0f * sk_v3f_length(view) * tan_half;
        cam->half_height = c->ortho_height / 2;
        cam->pixel_size = c->ortho_height / height;
    } else {
        cam->half_height = tan_half;
        cam->pixel_angle = 2.0f * tan_half / height;
    }
    cam->half_width = cam->half_height * width / height;
}

void sk__camera_ray(const sk__camera *cam, float x, float y, sk_vec3f *origin, sk_vec3f *dir)
{
    float nx = (2.0f * x / cam->width - 1.0f) * cam->half_width;
    float ny = (1.0f - 2.0f * y / cam->height) * cam->half_height;
    sk_vec3f offset = sk_v3f_add(sk_v3f_scale(cam->right, nx), sk_v3f_scale(cam->up, ny));
    if (cam->projection == SK_RENDER_PROJECTION_ORTHOGRAPHIC) {
        *origin = sk_v3f_add(cam->position, offset);
        *dir = cam->forward;
    } else {
        *origin = cam->position;
        *dir = sk_v3f_normalize(sk_v3f_add(cam->forward, offset));
    }
}

float sk__camera_footprint(const sk__camera *cam, float t)
{
    return cam->projection == SK_RENDER_PROJECTION_ORTHOGRAPHIC ? cam->pixel_size
                                                                : t * cam->pixel_angle;
}
