/* Private structures of the renderer: the built scene (meshes, instances, materials,
 * lights, camera) and the shading record passed between its stages. */
#ifndef SK_RENDER_INTERNAL_H
#define SK_RENDER_INTERNAL_H

#include <embree3/rtcore.h>

#include "shitsukan/render.h"

/* One unique triangle mesh with its own Embree scene (instanced by objects). */
typedef struct sk__rmesh {
    RTCScene rtc;
    sk_mesh mesh;          /* owned; normals NULL: shaded flat; uvs NULL: u = v = 0 */
    const float *tangents; /* the mesh's "tangent" attribute: xyz + handedness */
    sk_vec3f lo, hi;       /* bounds in the object frame */
} sk__rmesh;

/* An object: a mesh placed by an affine transform. */
typedef struct sk__instance {
    int mesh;
    int material;           /* index into scene->materials (the default is last) */
    sk_mat4f to_world;      /* object -> scene */
    sk_mat4f to_object;     /* scene -> object */
    sk_mat3f normal_matrix; /* inverse transpose of the linear part */
    sk_mat3f rotation;      /* the rotation alone (the object frame of solid textures) */
    float handedness;       /* sign of the linear part's determinant */
} sk__instance;

typedef struct sk__texture {
    sk_image image;                 /* linear floats, 1-4 channels */
    char name[SK_RENDER_PATH_SIZE]; /* as the scene names it */
    bool srgb;                      /* decoded from sRGB (colour) or read linearly */
    bool borrowed;                  /* image is the caller's (C API images): not freed */
} sk__texture;

typedef enum sk__brdf_kind {
    SK__BRDF_BLINN_PHONG = 0, /* diffuse + normalised Blinn-Phong */
    SK__BRDF_WOOD             /* sk_wood_shade: figure sheen or fibre highlight */
} sk__brdf_kind;

typedef struct sk__material {
    sk_render_material_desc desc; /* resolved */
    sk__brdf_kind brdf;
    int albedo_texture;  /* index into scene->textures, or -1 */
    int normal_map;      /* index into scene->textures, or -1 */
    sk_skin *skin;       /* type skin: the microrelief */
    const sk_wood *wood; /* type wood: the solid texture */
    sk_wood *owned_wood; /* the same when the scene built it (not the desc's wood_tree) */
    float wood_kd;       /* type wood: diffuse weight (lights the environment term) */
} sk__material;

typedef struct sk__camera {
    sk_render_projection projection;
    sk_vec3f position, forward, right, up; /* right and up unit */
    float width, height;                   /* image size in pixels */
    float half_width, half_height;         /* perspective: tan extents; ortho: scene units */
    float pixel_angle;                     /* perspective: radians per pixel (footprints) */
    float pixel_size;                      /* orthographic: scene units per pixel */
} sk__camera;

typedef struct sk__light {
    sk_render_light_type type;
    sk_vec3f power;          /* color * intensity */
    sk_vec3f position;       /* point: the light; rect: its centre */
    sk_vec3f direction;      /* directional: unit travel direction; rect: unit normal */
    sk_vec3f edge_u, edge_v; /* rect: full edge vectors (width, height); disc: unit */
    float area;
    float radius; /* sphere, disc */
    int samples;
    bool shadows;
} sk__light;

/* A piecewise-constant density over [0, 1)^2 (distribution.c). */
typedef struct sk__distribution2d {
    int width, height;
    float *func;         /* width x height, row-major, row 0 at v = 0 */
    float *conditional;  /* height rows of width + 1 CDF values */
    float *row_integral; /* height */
    float *marginal;     /* height + 1 CDF values */
    float integral;      /* of func over [0, 1)^2 */
} sk__distribution2d;

/* The environment light (environment.c). */
typedef struct sk__environment {
    sk_render_environment_type type;
    sk_vec3f uniform;  /* uniform: its radiance; map, sky: the mean radiance */
    int width, height; /* map, sky: lat-long table */
    float *rgb;        /* map, sky: radiance, strength applied */
    sk__distribution2d distribution;
    float cos_rot, sin_rot;
} sk__environment;

struct sk_render_scene {
    sk_render_scene_desc desc; /* resolved, camera framing included */
    RTCDevice device;
    RTCScene top;
    sk__rmesh *meshes;
    int mesh_count;
    sk__instance instances[SK_RENDER_MAX_OBJECTS];
    int instance_count;
    sk__material materials[SK_RENDER_MAX_MATERIALS + 1]; /* + the default material */
    int material_count;                                  /* including the default */
    sk__texture *textures;
    int texture_count;
    sk__camera camera;
    sk__light lights[SK_RENDER_MAX_LIGHTS];
    int light_count;
    sk__environment env;
    bool has_bounds;
    sk_vec3f lo, hi;
    enum RTCError rtc_error; /* first error Embree reported while building */
    char rtc_message[160];
};

/* Everything known about a camera-ray hit, in the scene frame. */
typedef struct sk__shading {
    sk_render_surface surface; /* point, normals, tangent frame, uv, st, footprint */
    sk_vec3f geometric_normal; /* unit, facing the viewer */
    sk_vec3f shading_normal;   /* after bump / normal maps, facing the viewer */
    sk_vec3f to_viewer;        /* unit, from the point towards the camera */
    float du_len, dv_len;      /* scene length per unit of u and v (0: no UV metric) */
    const sk__instance *instance;
    const sk__material *material;
    sk_render_texel texel;
    float lobe_norm;        /* K(shininess) of the Blinn-Phong lobe */
    sk_wood_sample wood;    /* wood: the solid texture at the point (object frame) */
    sk_vec3f texture_color; /* the texture/shading blend's unlit colour */
} sk__shading;

/* ---- geometry (scene_geometry.c) */
sk_result sk__geometry_build(sk_render_scene *scene, sk_error *err);
void sk__geometry_destroy(sk_render_scene *scene);
/* Fills the geometric part of `sh` for a hit of Embree's ray (instance, triangle, u, v),
 * with normals as the mesh winds. */
void sk__geometry_hit(const sk_render_scene *scene, unsigned instance, unsigned triangle, float u,
                      float v, sk__shading *sh);
/* Sets to_viewer and turns the frame to face the viewer (on the back of a surface normal,
 * tangent and bitangent are all negated: the same height field seen from behind). */
void sk__shading_face(sk__shading *sh, sk_vec3f ray_dir);

static inline void sk__rtc_ray(struct RTCRay *ray, sk_vec3f o, sk_vec3f d, float tnear, float tfar)
{
    ray->org_x = o.x, ray->org_y = o.y, ray->org_z = o.z;
    ray->dir_x = d.x, ray->dir_y = d.y, ray->dir_z = d.z;
    ray->tnear = tnear;
    ray->tfar = tfar;
    ray->time = 0.0f;
    ray->mask = 0xffffffffu;
    ray->id = 0;
    ray->flags = 0;
}

/* Closest hit; true if the ray hit something (rh->ray.tfar is then its distance). */
static inline bool sk__trace(const sk_render_scene *scene, struct RTCRayHit *rh)
{
    struct RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    rh->hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh->hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene->top, &ctx, rh);
    return rh->hit.geomID != RTC_INVALID_GEOMETRY_ID;
}

/* True if anything lies on the segment o + t d, 0 < t < tfar. */
static inline bool sk__occluded(const sk_render_scene *scene, sk_vec3f o, sk_vec3f d, float tfar)
{
    struct RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    struct RTCRay ray;
    sk__rtc_ray(&ray, o, d, 0.0f, tfar);
    rtcOccluded1(scene->top, &ctx, &ray);
    return ray.tfar < 0.0f;
}

/* ---- materials (material.c, texture.c) */
sk_result sk__materials_build(sk_render_scene *scene, sk_error *err);
void sk__materials_destroy(sk_render_scene *scene);
/* Completes `sh` (texel and shading normal) for the hit's material. */
void sk__material_eval(const sk_render_scene *scene, sk__shading *sh);
/* Reflected radiance per unit of incident radiance-times-solid-angle: f(wi, wo) cos(theta_i)
 * at the shading point (wi unit, towards the light). */
sk_vec3f sk__material_reflect(const sk__shading *sh, sk_vec3f wi);
/* K(n) normalising the Blinn-Phong lobe K (N.H)^n to directional albedo 1 at normal
 * incidence. */
float sk__blinn_phong_norm(float n);
/* Samples a direction wi (unit) by the reflection at the shading point (material_sample.c)
 * with two uniform numbers for the direction and one for the lobe; *pdf per solid angle.
 * False: no direction above the shading horizon. */
bool sk__material_sample(const sk__shading *sh, sk_vec2f u, float u_lobe, sk_vec3f *wi, float *pdf);
/* The density sk__material_sample gives wi. */
float sk__material_pdf(const sk__shading *sh, sk_vec3f wi);
/* Albedo seen by the uniform environment (diffuse part + the lobe's directional albedo). */
sk_vec3f sk__material_ambient_albedo(const sk__shading *sh);

/* Type-specific parts (material_skin.c). */
sk_result sk__skin_material_build(sk__material *m, int index, sk_error *err);
void sk__skin_material_destroy(sk__material *m);
/* Adds the skin's height gradient at st (mm) to the texel's slope. */
void sk__skin_material_texel(const sk__material *m, const sk_render_surface *s,
                             sk_render_texel *tx);
/* (material_wood.c) */
sk_result sk__wood_material_build(sk__material *m, int index, sk_error *err);
void sk__wood_material_destroy(sk__material *m);
/* Evaluates the wood at the shading point: sh->wood and the texel's albedo. */
void sk__wood_material_texel(const sk_render_scene *scene, sk__shading *sh);
sk_vec3f sk__wood_material_reflect(const sk__shading *sh, sk_vec3f wi);

sk_result sk__texture_load(sk__texture *tex, const char *path, bool srgb, sk_error *err);
/* Bilinear lookup with repeat wrapping; t = 0 at the image bottom. Writes 4 channels
 * (missing ones: grey replicated, alpha 1). */
void sk__texture_sample(const sk__texture *tex, sk_vec2f st, float out[4]);

/* ---- camera (camera.c) */
void sk__camera_setup(sk_render_scene *scene);
/* Ray through image position (x, y) in pixels (continuous, 0 at the top-left corner). */
void sk__camera_ray(const sk__camera *cam, float x, float y, sk_vec3f *origin, sk_vec3f *dir);
/* Width of a pixel's footprint at ray distance t (scene units). */
float sk__camera_footprint(const sk__camera *cam, float t);

/* ---- lights (lights.c) */
void sk__lights_setup(sk_render_scene *scene);
/* Samples light `l` seen from point p with a uniform 2D sample: the unit direction towards
 * the light, the distance to it (INFINITY for directional), and the incident radiance
 * times the solid-angle measure divided by the sample density (so the estimate of the
 * reflected radiance is reflect(wi) * weight). False if the sample carries no light. */
bool sk__light_sample(const sk__light *l, sk_vec3f p, sk_vec2f u, sk_vec3f *wi, float *dist,
                      sk_vec3f *weight);

static inline bool sk__light_is_area(sk_render_light_type t)
{
    return t == SK_RENDER_LIGHT_RECT || t == SK_RENDER_LIGHT_SPHERE || t == SK_RENDER_LIGHT_DISC;
}

/* ---- area lights (area_lights.c) */
/* Samples a point of area light `l` seen from p: direction, distance and the solid-angle
 * density of the sample (the incident radiance is l->power). False: no light this way. */
bool sk__area_light_sample(const sk__light *l, sk_vec3f p, sk_vec2f u, sk_vec3f *wi, float *dist,
                           float *pdf);
/* The solid-angle density sk__area_light_sample gives direction wi from p when the ray
 * p + t wi reaches the light at t. */
float sk__area_light_pdf(const sk__light *l, sk_vec3f p, sk_vec3f wi, float t);
/* True if the ray o + t d (d unit) meets the light's emitting side at 0 < t < tmax. */
bool sk__area_light_hit(const sk__light *l, sk_vec3f o, sk_vec3f d, float tmax, float *t);

/* ---- environment (environment.c, distribution.c) */
sk_result sk__environment_build(sk_render_scene *scene, sk_error *err);
void sk__environment_destroy(sk_render_scene *scene);
bool sk__environment_is_black(const sk__environment *env);
/* Radiance arriving from direction d (unit, towards the environment). */
sk_vec3f sk__environment_eval(const sk__environment *env, sk_vec3f d);
/* Samples a direction by the environment's radiance; *pdf per solid angle. */
sk_vec3f sk__environment_sample(const sk__environment *env, sk_vec2f u, float *pdf);
float sk__environment_pdf(const sk__environment *env, sk_vec3f d);
sk_result sk__distribution2d_build(sk__distribution2d *d, const float *func, int w, int h,
                                   sk_error *err);
void sk__distribution2d_free(sk__distribution2d *d);
/* A point in [0, 1)^2 by the density, with the density there. */
sk_vec2f sk__distribution2d_sample(const sk__distribution2d *d, sk_vec2f u, float *pdf);
float sk__distribution2d_pdf(const sk__distribution2d *d, sk_vec2f uv);

/* ---- small helpers */
static inline bool sk__v3f_is_zero(const float a[3]) { return a[0] == 0 && a[1] == 0 && a[2] == 0; }
/* Fills a material desc's zero defaults in place. */
void sk__material_desc_resolve(sk_render_material_desc *m);
/* Object-to-scene matrix of a transform desc (resolved scale), and its rotation alone. */
sk_mat4f sk__transform_matrix(const sk_render_transform *t);
sk_mat3f sk__transform_rotation(const sk_render_transform *t);
/* `name` resolved against the folder `base` ("" = as is; absolute names stay as they are). */
void sk__join_path(const char *base, const char *name, char *out, size_t size);
/* True if `path` ends in `ext` (".png"), ignoring case. */
bool sk__has_extension(const char *path, const char *ext);

/* ---- the parts of sk_render_schema (render_schema.c), each checked and resolved on its
   own (the whole desc is large) */
extern const sk_schema sk__render_object_schema, sk__render_material_schema,
    sk__render_light_schema, sk__render_camera_schema, sk__render_environment_schema,
    sk__render_image_schema, sk__render_film_schema;

#endif
