/* Scene file schema: every key of a scene JSON with its type, range, default and doc, stated
 * once (bound onto sk_render_scene_desc by the preset binder, which names the key path in
 * every error; sk_render_scene_desc_validate and the resolve read the same table). */
#include <stddef.h>

#include "render/render_internal.h"

#define BIG 1e9 /* coordinates: any finite value within reason */

const char *const sk_render_shape_names[] = {"mesh",     "plane",   "box", "sphere",
                                             "cylinder", "capsule", NULL};
const char *const sk_render_uv_mode_names[] = {"length", "unit", NULL};
const char *const sk_render_projection_names[] = {"perspective", "orthographic", NULL};
const char *const sk_render_light_type_names[] = {"directional", "point", "rect",
                                                  "sphere",      "disc",  NULL};
const char *const sk_render_integrator_names[] = {"preview", "path", "path_bsdf", NULL};
const char *const sk_render_environment_type_names[] = {"uniform", "map", "sky", NULL};
const char *const sk_render_material_type_names[] = {"standard", "skin", "wood", NULL};
const char *const sk_render_tonemap_names[] = {"clamp", "reinhard", "filmic", NULL};

static const double ones[3] = {1, 1, 1};
static const double up_y[3] = {0, 1, 0};
static const double grey[3] = {0.8, 0.8, 0.8};
static const double sun_direction[3] = {0.4, 0.7, 0.3};
static const double sky_zenith[3] = {0.2, 0.35, 0.8};
static const double sky_horizon[3] = {0.8, 0.85, 0.9};
static const double sky_ground[3] = {0.2, 0.18, 0.16};

/* ---- transform */
static const sk_schema_field transform_fields[] = {
    SK_SCHEMA_FLOATS(sk_render_transform, translate, "translate", 3, -BIG, BIG,
                     .doc = "translation in scene units"),
    SK_SCHEMA_FLOATS(
        sk_render_transform, rotate, "rotate_deg", 3, -3600, 3600, .scale = SK_DEG_TO_RAD,
        .doc = "rotations about X, Y, Z in degrees, applied in that order after scaling"),
    SK_SCHEMA_FLOATS(sk_render_transform, scale, "scale", 3, -BIG, BIG, .defs = ones,
                     .doc = "per-axis scale (none 0)"),
};
static const sk_schema transform_schema =
    SK_SCHEMA_OF("transform", sk_render_transform, transform_fields);

/* ---- objects */
static const sk_schema_field object_fields[] = {
    SK_SCHEMA_STRING(sk_render_object_desc, name, "name", .doc = "name for messages"),
    SK_SCHEMA_ENUM(sk_render_object_desc, shape, "shape", sk_render_shape_names,
                   .doc = "mesh (from file), plane, box, sphere, cylinder or capsule"),
    SK_SCHEMA_STRING(sk_render_object_desc, file, "file",
                     .doc = "OBJ or PLY file of a mesh, relative to the scene file"),
    SK_SCHEMA_FLOATS(sk_render_object_desc, size, "size", 3, 0, BIG, .defs = ones,
                     .doc = "box edge lengths; plane: size[0] x size[2]"),
    SK_SCHEMA_FLOAT(sk_render_object_desc, radius, "radius", 1e-30, BIG, .flags = SK_FIELD_ZERO,
                    .def = 0.5, .doc = "sphere, cylinder, capsule radius"),
    SK_SCHEMA_FLOAT(sk_render_object_desc, height, "height", 1e-30, BIG, .flags = SK_FIELD_ZERO,
                    .def = 1, .doc = "cylinder, capsule: length of the straight part along y"),
    SK_SCHEMA_INT(sk_render_object_desc, segments, "segments", 3, 4096, .def = 64,
                  .doc = "tessellation around y"),
    SK_SCHEMA_INT(sk_render_object_desc, rings, "rings", 2, 4096, .def = 32,
                  .doc = "tessellation pole to pole"),
    SK_SCHEMA_ENUM(sk_render_object_desc, uv, "uv", sk_render_uv_mode_names,
                   .doc = "primitive UVs: length (arc length, scene units) or unit ([0, 1])"),
    SK_SCHEMA_STRING(sk_render_object_desc, material, "material",
                     .doc = "name of a material (none: grey diffuse)"),
    SK_SCHEMA_OBJECT(sk_render_object_desc, transform, "transform", transform_schema,
                     .doc = "placement in the scene"),
};
const sk_schema sk__render_object_schema =
    SK_SCHEMA_OF("object", sk_render_object_desc, object_fields);

/* ---- materials */
static const sk_schema_field preset_set_fields[] = {
    SK_SCHEMA_STRING(sk_render_preset_set, text, NULL, .doc = "key.path=value"),
};
static const sk_schema preset_set_schema =
    SK_SCHEMA_OF("preset_set", sk_render_preset_set, preset_set_fields);

static const sk_schema_field material_fields[] = {
    SK_SCHEMA_STRING(sk_render_material_desc, name, "name", .doc = "unique name objects refer to"),
    SK_SCHEMA_ENUM(sk_render_material_desc, type, "type", sk_render_material_type_names,
                   .doc = "standard (diffuse + Blinn-Phong), skin or wood"),
    SK_SCHEMA_FLOATS(sk_render_material_desc, albedo, "albedo", 3, 0, 1, .defs = grey,
                     .doc = "linear diffuse reflectance"),
    SK_SCHEMA_STRING(sk_render_material_desc, albedo_texture, "albedo_texture",
                     .doc = "PNG (sRGB) or EXR image multiplying albedo, one repeat per st unit"),
    SK_SCHEMA_FLOAT(sk_render_material_desc, specular, "specular", 0, 1,
                    .doc = "ks, weight of the Blinn-Phong lobe (diffuse gets 1 - ks)"),
    SK_SCHEMA_FLOAT(sk_render_material_desc, shininess, "shininess", 1, 100000, .def = 64,
                    .doc = "Blinn-Phong exponent"),
    SK_SCHEMA_STRING(sk_render_material_desc, normal_map, "normal_map",
                     .doc = "tangent-space normal map (PNG read linearly, or EXR; +y = +v)"),
    SK_SCHEMA_FLOAT(sk_render_material_desc, bump_scale, "bump_scale", 0, 100, .def = 1,
                    .doc = "multiplies every height gradient"),
    SK_SCHEMA_FLOATS(sk_render_material_desc, uv_scale, "uv_scale", 2, -BIG, BIG, .defs = ones,
                     .doc = "st = uv * uv_scale + uv_offset"),
    SK_SCHEMA_FLOATS(sk_render_material_desc, uv_offset, "uv_offset", 2, -BIG, BIG,
                     .doc = "st = uv * uv_scale + uv_offset"),
    SK_SCHEMA_FLOAT(
        sk_render_material_desc, texture_weight, "texture_weight", 0, 1,
        .doc = "hand-thesis blend: (1 - w) shading of white + w texture (0: off; the thesis: 0.7)"),
    SK_SCHEMA_FLOAT(sk_render_material_desc, texture_radiance, "texture_radiance", 0, BIG, .def = 1,
                    .doc = "radiance of albedo 1 in the blend"),
    SK_SCHEMA_STRING(sk_render_material_desc, skin_preset, "skin_preset",
                     .doc = "skin: a skin preset name or JSON file (instead of `skin`)"),
    SK_SCHEMA_ARRAY(sk_render_material_desc, skin_set, "skin_set", skin_set_count, 0,
                    preset_set_schema, .doc = "skin: edits of skin_preset, e.g. [\"seed=3\"]"),
    SK_SCHEMA_OBJECT(sk_render_material_desc, skin, "skin", sk_skin_schema, .flags = SK_FIELD_OWN,
                     .doc = "skin: the skin desc itself (keys as in presets/skin)"),
    SK_SCHEMA_STRING(sk_render_material_desc, wood_preset, "wood_preset",
                     .doc = "wood: a wood preset name or JSON file (instead of `wood`)"),
    SK_SCHEMA_ARRAY(sk_render_material_desc, wood_set, "wood_set", wood_set_count, 0,
                    preset_set_schema,
                    .doc = "wood: edits of wood_preset, e.g. [\"shading.specular=0.2\"]"),
    SK_SCHEMA_OBJECT(sk_render_material_desc, wood, "wood", sk_wood_schema, .flags = SK_FIELD_OWN,
                     .doc = "wood: the wood desc itself (keys as in presets/wood)"),
};
const sk_schema sk__render_material_schema =
    SK_SCHEMA_OF("material", sk_render_material_desc, material_fields);

/* ---- lights */
static const sk_schema_field light_fields[] = {
    SK_SCHEMA_ENUM(sk_render_light_desc, type, "type", sk_render_light_type_names,
                   .doc = "directional, point, rect, sphere or disc"),
    SK_SCHEMA_FLOATS(sk_render_light_desc, color, "color", 3, 0, BIG, .defs = ones,
                     .doc = "linear RGB tint"),
    SK_SCHEMA_FLOAT(sk_render_light_desc, intensity, "intensity", 0, BIG,
                    .def_text = "irradiance pi at the camera target",
                    .doc = "irradiance W/m2 (directional), intensity W/sr (point), radiance W/(sr "
                           "m2) (rect, sphere, disc)"),
    SK_SCHEMA_FLOATS(sk_render_light_desc, position, "position", 3, -BIG, BIG,
                     .doc = "point: position; rect, sphere, disc: centre"),
    SK_SCHEMA_FLOATS(sk_render_light_desc, direction, "direction", 3, -BIG, BIG,
                     .def_text = "down (directional), towards the target (rect, disc)",
                     .doc = "directional: direction of travel; rect, disc: emitting side"),
    SK_SCHEMA_FLOATS(sk_render_light_desc, size, "size", 2, 0, BIG, .defs = ones,
                     .doc = "rect: width and height"),
    SK_SCHEMA_FLOAT(sk_render_light_desc, radius, "radius", 1e-30, BIG, .flags = SK_FIELD_ZERO,
                    .def = 0.5, .doc = "sphere, disc: radius"),
    SK_SCHEMA_FLOATS(sk_render_light_desc, up, "up", 3, -BIG, BIG, .defs = up_y,
                     .doc = "rect: direction of the height edge"),
    SK_SCHEMA_INT(sk_render_light_desc, samples, "samples", 1, 256, .def = 1,
                  .doc = "rect, sphere, disc: shadow rays per camera sample (preview)"),
    SK_SCHEMA_BOOL(sk_render_light_desc, no_shadows, "no_shadows", .doc = "skip shadow rays"),
};
const sk_schema sk__render_light_schema = SK_SCHEMA_OF("light", sk_render_light_desc, light_fields);

/* ---- camera, environment, image, film */
static const sk_schema_field camera_fields[] = {
    SK_SCHEMA_ENUM(sk_render_camera_desc, projection, "projection", sk_render_projection_names,
                   .doc = "perspective or orthographic"),
    SK_SCHEMA_FLOATS(sk_render_camera_desc, position, "position", 3, -BIG, BIG,
                     .doc = "eye (position and target all 0: frame the scene)"),
    SK_SCHEMA_FLOATS(sk_render_camera_desc, target, "target", 3, -BIG, BIG,
                     .doc = "point at the image centre"),
    SK_SCHEMA_FLOATS(sk_render_camera_desc, up, "up", 3, -BIG, BIG, .defs = up_y,
                     .doc = "up in the image"),
    SK_SCHEMA_DEG(sk_render_camera_desc, fov, "fov_deg", 0.001, 179, .def = 40,
                  .doc = "vertical field of view in degrees"),
    SK_SCHEMA_FLOAT(sk_render_camera_desc, ortho_height, "ortho_height", 0, BIG,
                    .def_text = "what the fov sees at the target",
                    .doc = "orthographic view height in scene units"),
};
const sk_schema sk__render_camera_schema =
    SK_SCHEMA_OF("camera", sk_render_camera_desc, camera_fields);

static const sk_schema_field environment_fields[] = {
    SK_SCHEMA_ENUM(sk_render_environment_desc, type, "type", sk_render_environment_type_names,
                   .doc = "uniform (radiance), map (lat-long EXR) or sky (procedural)"),
    SK_SCHEMA_FLOATS(sk_render_environment_desc, radiance, "radiance", 3, 0, BIG,
                     .doc = "uniform sky radiance, linear RGB"),
    SK_SCHEMA_STRING(
        sk_render_environment_desc, map, "map",
        .doc = "map: lat-long EXR (centre column -z, top row +y), relative to the scene file"),
    SK_SCHEMA_FLOAT(sk_render_environment_desc, strength, "strength", 0, BIG, .def = 1,
                    .doc = "map, sky: multiplies the radiance"),
    SK_SCHEMA_DEG(sk_render_environment_desc, rotate, "rotate_deg", -3600, 3600,
                  .doc = "map: turn about +y in degrees"),
    SK_SCHEMA_FLOATS(sk_render_environment_desc, sun_direction, "sun_direction", 3, -BIG, BIG,
                     .defs = sun_direction, .doc = "sky: towards the sun"),
    SK_SCHEMA_FLOAT(sk_render_environment_desc, sun_irradiance, "sun_irradiance", 0, BIG, .def = 5,
                    .doc = "sky: irradiance W/m2 of the sun on a surface facing it"),
    SK_SCHEMA_DEG(sk_render_environment_desc, sun_size, "sun_size_deg", 0.5, 45,
                  .flags = SK_FIELD_ZERO, .def = 3,
                  .doc = "sky: angular diameter of the sun in degrees"),
    SK_SCHEMA_FLOATS(sk_render_environment_desc, zenith, "zenith", 3, 0, BIG, .defs = sky_zenith,
                     .doc = "sky: radiance at the zenith"),
    SK_SCHEMA_FLOATS(sk_render_environment_desc, horizon, "horizon", 3, 0, BIG, .defs = sky_horizon,
                     .doc = "sky: radiance at the horizon"),
    SK_SCHEMA_FLOATS(sk_render_environment_desc, ground, "ground", 3, 0, BIG, .defs = sky_ground,
                     .doc = "sky: radiance below the horizon"),
    SK_SCHEMA_BOOL(sk_render_environment_desc, ambient_occlusion, "ambient_occlusion",
                   .doc = "trace occlusion rays"),
    SK_SCHEMA_FLOAT(sk_render_environment_desc, ao_distance, "ao_distance", 0, BIG,
                    .def_text = "unlimited", .doc = "length of occlusion rays"),
    SK_SCHEMA_INT(sk_render_environment_desc, ao_samples, "ao_samples", 1, 256, .def = 1,
                  .doc = "occlusion rays per camera sample"),
};
const sk_schema sk__render_environment_schema =
    SK_SCHEMA_OF("environment", sk_render_environment_desc, environment_fields);

static const sk_schema_field image_fields[] = {
    SK_SCHEMA_INT(sk_render_image_desc, width, "width", 1, SK_RENDER_MAX_DIMENSION, .def = 640,
                  .doc = "image width, pixels"),
    SK_SCHEMA_INT(sk_render_image_desc, height, "height", 1, SK_RENDER_MAX_DIMENSION, .def = 360,
                  .doc = "image height, pixels"),
    SK_SCHEMA_INT(sk_render_image_desc, samples, "samples", 1, SK_RENDER_MAX_SAMPLES, .def = 16,
                  .doc = "camera samples per pixel"),
};
const sk_schema sk__render_image_schema = SK_SCHEMA_OF("image", sk_render_image_desc, image_fields);

static const sk_schema_field film_fields[] = {
    SK_SCHEMA_FLOAT(sk_render_film_desc, exposure, "exposure", -30, 30, .doc = "exposure in stops"),
    SK_SCHEMA_ENUM(sk_render_film_desc, tonemap, "tonemap", sk_render_tonemap_names,
                   .doc = "tone curve: clamp, reinhard or filmic"),
    SK_SCHEMA_FLOAT(sk_render_film_desc, white, "white", 0, 1e6, .def_text = "none",
                    .doc = "reinhard: radiance that maps to white"),
    SK_SCHEMA_BOOL(sk_render_film_desc, opaque, "opaque",
                   .doc = "fill the background with `background` (false: transparent)"),
    SK_SCHEMA_FLOATS(sk_render_film_desc, background, "background", 3, 0, BIG,
                     .doc = "background radiance when opaque"),
    SK_SCHEMA_ENUM(sk_render_film_desc, integrator, "integrator", sk_render_integrator_names,
                   .doc = "preview (direct light + AO), path (path tracing, NEE + MIS) or "
                          "path_bsdf (BSDF sampling only, a reference)"),
    SK_SCHEMA_INT(sk_render_film_desc, max_bounces, "max_bounces", 1, 1024, .def = 8,
                  .doc = "path: surface scatterings per path (1 = direct light only)"),
};
const sk_schema sk__render_film_schema = SK_SCHEMA_OF("film", sk_render_film_desc, film_fields);

/* ---- scene */
static const sk_schema_field scene_fields[] = {
    SK_SCHEMA_SEED(sk_render_scene_desc, seed, "seed", .doc = "seed of every random sample"),
    SK_SCHEMA_FLOAT(sk_render_scene_desc, unit_mm, "unit_mm", 1e-6, 1e9, .def = 1,
                    .doc = "millimetres per scene unit"),
    SK_SCHEMA_OBJECT(sk_render_scene_desc, image, "image", sk__render_image_schema,
                     .doc = "size and samples"),
    SK_SCHEMA_OBJECT(sk_render_scene_desc, film, "film", sk__render_film_schema,
                     .doc = "exposure, tone curve, background"),
    SK_SCHEMA_OBJECT(sk_render_scene_desc, camera, "camera", sk__render_camera_schema,
                     .doc = "view"),
    SK_SCHEMA_OBJECT(sk_render_scene_desc, environment, "environment",
                     sk__render_environment_schema, .doc = "ambient light and occlusion"),
    SK_SCHEMA_ARRAY(sk_render_scene_desc, materials, "materials", material_count, 0,
                    sk__render_material_schema, .doc = "materials"),
    SK_SCHEMA_ARRAY(sk_render_scene_desc, objects, "objects", object_count, 0,
                    sk__render_object_schema, .doc = "objects"),
    SK_SCHEMA_ARRAY(sk_render_scene_desc, lights, "lights", light_count, 0, sk__render_light_schema,
                    .doc = "lights"),
};
const sk_schema sk_render_schema = SK_SCHEMA_OF("scene", sk_render_scene_desc, scene_fields);
