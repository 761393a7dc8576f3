/* Scene file schema: every key of a scene JSON with its type, range and doc (bound onto
 * sk_render_scene_desc by the preset binder, which names the key path in every error). */
#include <stddef.h>

#include "render/render_internal.h"

#define BIG 1e9 /* coordinates: any finite value within reason */

const char *const sk_render_shape_names[] = {"mesh", "plane", "box", "sphere", "cylinder",
                                             "capsule", NULL};
const char *const sk_render_uv_mode_names[] = {"length", "unit", NULL};
const char *const sk_render_projection_names[] = {"perspective", "orthographic", NULL};
const char *const sk_render_light_type_names[] = {"directional", "point", "rect", NULL};
const char *const sk_render_material_type_names[] = {"standard", "skin", "wood", NULL};
const char *const sk_render_tonemap_names[] = {"clamp", "reinhard", "filmic", NULL};

#define FLOAT3(k, T, field, lo, hi, d)                                                             \
    {.key = k, .type = SK_FIELD_FLOATS, .offset = offsetof(T, field), .min = lo, .max = hi,       \
     .count = 3, .count_offset = SK_FIELD_FIXED, .doc = d}
#define FLOAT2(k, T, field, lo, hi, d)                                                             \
    {.key = k, .type = SK_FIELD_FLOATS, .offset = offsetof(T, field), .min = lo, .max = hi,       \
     .count = 2, .count_offset = SK_FIELD_FIXED, .doc = d}

/* ---- transform */
static const sk_schema_field transform_fields[] = {
    FLOAT3("translate", sk_render_transform, translate, -BIG, BIG, "translation in scene units; default 0"),
    {.key = "rotate_deg", .type = SK_FIELD_FLOATS, .offset = offsetof(sk_render_transform, rotate),
     .min = -3600, .max = 3600, .scale = SK_DEG_TO_RAD, .count = 3, .count_offset = SK_FIELD_FIXED,
     .doc = "rotations about X, Y, Z in degrees, applied in that order after scaling; default 0"},
    FLOAT3("scale", sk_render_transform, scale, -BIG, BIG, "per-axis scale; all 0 = 1; default 1"),
};
static const sk_schema transform_schema = {"transform", transform_fields,
                                           sizeof transform_fields / sizeof transform_fields[0]};

/* ---- objects */
static const sk_schema_field object_fields[] = {
    {.key = "name", .type = SK_FIELD_STRING, .offset = offsetof(sk_render_object_desc, name),
     .count = SK_RENDER_NAME_SIZE, .doc = "name for messages"},
    {.key = "shape", .type = SK_FIELD_ENUM, .offset = offsetof(sk_render_object_desc, shape),
     .names = sk_render_shape_names, .doc = "mesh (from file), plane, box, sphere, cylinder or capsule; default mesh"},
    {.key = "file", .type = SK_FIELD_STRING, .offset = offsetof(sk_render_object_desc, file),
     .count = SK_RENDER_PATH_SIZE, .doc = "OBJ or PLY file of a mesh, relative to the scene file"},
    FLOAT3("size", sk_render_object_desc, size, 0, BIG, "box edge lengths; plane: size[0] x size[2]; default 1"),
    {.key = "radius", .type = SK_FIELD_FLOAT, .offset = offsetof(sk_render_object_desc, radius),
     .min = 0, .max = BIG, .doc = "sphere, cylinder, capsule radius; 0 = 0.5"},
    {.key = "height", .type = SK_FIELD_FLOAT, .offset = offsetof(sk_render_object_desc, height),
     .min = 0, .max = BIG, .doc = "cylinder, capsule: length of the straight part along y; 0 = 1"},
    {.key = "segments", .type = SK_FIELD_INT, .offset = offsetof(sk_render_object_desc, segments),
     .min = 3, .max = 4096, .doc = "tessellation around y; default 64"},
    {.key = "rings", .type = SK_FIELD_INT, .offset = offsetof(sk_render_object_desc, rings),
     .min = 2, .max = 4096, .doc = "tessellation pole to pole; default 32"},
    {.key = "uv", .type = SK_FIELD_ENUM, .offset = offsetof(sk_render_object_desc, uv),
     .names = sk_render_uv_mode_names, .doc = "primitive UVs: length (arc length, scene units) or unit ([0, 1]); default length"},
    {.key = "material", .type = SK_FIELD_STRING, .offset = offsetof(sk_render_object_desc, material),
     .count = SK_RENDER_NAME_SIZE, .doc = "name of a material; default: grey diffuse"},
    {.key = "transform", .type = SK_FIELD_OBJECT, .offset = offsetof(sk_render_object_desc, transform),
     .schema = &transform_schema, .doc = "placement in the scene"},
};
static const sk_schema object_schema = {"object", object_fields,
                                        sizeof object_fields / sizeof object_fields[0]};

/* ---- materials */
static const sk_schema_field preset_set_fields[] = {
    {.key = NULL, .type = SK_FIELD_STRING, .offset = offsetof(sk_render_preset_set, text),
     .count = sizeof(((sk_render_preset_set *)0)->text), .doc = "key.path=value"},
};
static const sk_schema preset_set_schema = {"preset_set", preset_set_fields, 1};

static const sk_schema_field material_fields[] = {
    {.key = "name", .type = SK_FIELD_STRING, .offset = offsetof(sk_render_material_desc, name),
     .count = SK_RENDER_NAME_SIZE, .doc = "unique name objects refer to"},
    {.key = "type", .type = SK_FIELD_ENUM, .offset = offsetof(sk_render_material_desc, type),
     .names = sk_render_material_type_names, .doc = "standard (diffuse + Blinn-Phong), skin or wood; default standard"},
    FLOAT3("albedo", sk_render_material_desc, albedo, 0, 1, "linear diffuse reflectance; all 0 = 0.8"),
    {.key = "albedo_texture", .type = SK_FIELD_STRING,
     .offset = offsetof(sk_render_material_desc, albedo_texture), .count = SK_RENDER_PATH_SIZE,
     .doc = "PNG (sRGB) or EXR image multiplying albedo, one repeat per st unit"},
    {.key = "specular", .type = SK_FIELD_FLOAT, .offset = offsetof(sk_render_material_desc, specular),
     .min = 0, .max = 1, .doc = "ks, weight of the Blinn-Phong lobe (diffuse gets 1 - ks); default 0"},
    {.key = "shininess", .type = SK_FIELD_FLOAT, .offset = offsetof(sk_render_material_desc, shininess),
     .min = 1, .max = 100000, .doc = "Blinn-Phong exponent; default 64"},
    {.key = "normal_map", .type = SK_FIELD_STRING, .offset = offsetof(sk_render_material_desc, normal_map),
     .count = SK_RENDER_PATH_SIZE, .doc = "tangent-space normal map (PNG read linearly, or EXR; +y = +v)"},
    {.key = "bump_scale", .type = SK_FIELD_FLOAT, .offset = offsetof(sk_render_material_desc, bump_scale),
     .min = 0, .max = 100, .doc = "multiplies every height gradient; 0 = 1"},
    FLOAT2("uv_scale", sk_render_material_desc, uv_scale, -BIG, BIG, "st = uv * uv_scale + uv_offset; all 0 = 1"),
    FLOAT2("uv_offset", sk_render_material_desc, uv_offset, -BIG, BIG, "default 0"),
    {.key = "texture_weight", .type = SK_FIELD_FLOAT,
     .offset = offsetof(sk_render_material_desc, texture_weight), .min = 0, .max = 1,
     .doc = "hand-thesis blend: (1 - w) shading of white + w texture; default 0 (off), thesis 0.7"},
    {.key = "texture_radiance", .type = SK_FIELD_FLOAT,
     .offset = offsetof(sk_render_material_desc, texture_radiance), .min = 0, .max = BIG,
     .doc = "radiance of albedo 1 in the blend; 0 = 1"},
    {.key = "skin_preset", .type = SK_FIELD_STRING, .offset = offsetof(sk_render_material_desc, skin_preset),
     .count = SK_RENDER_PATH_SIZE, .doc = "skin: a skin preset name or JSON file (instead of `skin`)"},
    {.key = "skin_set", .type = SK_FIELD_ARRAY, .offset = offsetof(sk_render_material_desc, skin_set),
     .count = SK_RENDER_MAX_PRESET_SETS, .count_offset = offsetof(sk_render_material_desc, skin_set_count),
     .elem_size = sizeof(sk_render_preset_set), .schema = &preset_set_schema,
     .doc = "skin: edits of skin_preset, e.g. [\"seed=3\"]"},
    {.key = "skin", .type = SK_FIELD_OBJECT, .offset = offsetof(sk_render_material_desc, skin),
     .schema = &sk_skin_schema, .doc = "skin: the skin desc itself (keys as in presets/skin)"},
    {.key = "wood_preset", .type = SK_FIELD_STRING, .offset = offsetof(sk_render_material_desc, wood_preset),
     .count = SK_RENDER_PATH_SIZE, .doc = "wood: a wood preset name or JSON file (instead of `wood`)"},
    {.key = "wood_set", .type = SK_FIELD_ARRAY, .offset = offsetof(sk_render_material_desc, wood_set),
     .count = SK_RENDER_MAX_PRESET_SETS, .count_offset = offsetof(sk_render_material_desc, wood_set_count),
     .elem_size = sizeof(sk_render_preset_set), .schema = &preset_set_schema,
     .doc = "wood: edits of wood_preset, e.g. [\"shading.specular=0.2\"]"},
    {.key = "wood", .type = SK_FIELD_OBJECT, .offset = offsetof(sk_render_material_desc, wood),
     .schema = &sk_wood_schema, .doc = "wood: the wood desc itself (keys as in presets/wood)"},
};
static const sk_schema material_schema = {"material", material_fields,
                                          sizeof material_fields / sizeof material_fields[0]};

/* ---- lights */
static const sk_schema_field light_fields[] = {
    {.key = "type", .type = SK_FIELD_ENUM, .offset = offsetof(sk_render_light_desc, type),
     .names = sk_render_light_type_names, .doc = "directional, point or rect; default directional"},
    FLOAT3("color", sk_render_light_desc, color, 0, BIG, "linear RGB tint; all 0 = white"),
    {.key = "intensity", .type = SK_FIELD_FLOAT, .offset = offsetof(sk_render_light_desc, intensity),
     .min = 0, .max = BIG,
     .doc = "irradiance W/m2 (directional), intensity W/sr (point), radiance W/(sr m2) (rect); 0 = irradiance pi at the camera target"},
    FLOAT3("position", sk_render_light_desc, position, -BIG, BIG, "point: position; rect: centre"),
    FLOAT3("direction", sk_render_light_desc, direction, -BIG, BIG,
           "directional: direction of travel (all 0 = down); rect: emitting side (all 0 = towards the target)"),
    FLOAT2("size", sk_render_light_desc, size, 0, BIG, "rect: width and height; all 0 = 1"),
    FLOAT3("up", sk_render_light_desc, up, -BIG, BIG, "rect: direction of the height edge; all 0 = +y"),
    {.key = "samples", .type = SK_FIELD_INT, .offset = offsetof(sk_render_light_desc, samples),
     .min = 1, .max = 256, .doc = "rect: shadow rays per camera sample; default 1"},
    {.key = "no_shadows", .type = SK_FIELD_BOOL, .offset = offsetof(sk_render_light_desc, no_shadows),
     .doc = "skip shadow rays; default false"},
};
static const sk_schema light_schema = {"light", light_fields,
                                       sizeof light_fields / sizeof light_fields[0]};

/* ---- camera, environment, image, film */
static const sk_schema_field camera_fields[] = {
    {.key = "projection", .type = SK_FIELD_ENUM, .offset = offsetof(sk_render_camera_desc, projection),
     .names = sk_render_projection_names, .doc = "perspective or orthographic; default perspective"},
    FLOAT3("position", sk_render_camera_desc, position, -BIG, BIG, "eye; position and target all 0 = frame the scene"),
    FLOAT3("target", sk_render_camera_desc, target, -BIG, BIG, "point at the image centre"),
    FLOAT3("up", sk_render_camera_desc, up, -BIG, BIG, "up in the image; all 0 = +y"),
    {.key = "fov_deg", .type = SK_FIELD_FLOAT, .offset = offsetof(sk_render_camera_desc, fov),
     .min = 0.001, .max = 179, .scale = SK_DEG_TO_RAD, .doc = "vertical field of view in degrees; default 40"},
    {.key = "ortho_height", .type = SK_FIELD_FLOAT, .offset = offsetof(sk_render_camera_desc, ortho_height),
     .min = 0, .max = BIG, .doc = "orthographic view height in scene units; 0 = what the fov sees at the target"},
};
static const sk_schema camera_schema = {"camera", camera_fields,
                                        sizeof camera_fields / sizeof camera_fields[0]};

static const sk_schema_field environment_fields[] = {
    FLOAT3("radiance", sk_render_environment_desc, radiance, 0, BIG, "uniform sky radiance, linear RGB; default 0"),
    {.key = "ambient_occlusion", .type = SK_FIELD_BOOL,
     .offset = offsetof(sk_render_environment_desc, ambient_occlusion), .doc = "trace occlusion rays; default false"},
    {.key = "ao_distance", .type = SK_FIELD_FLOAT, .offset = offsetof(sk_render_environment_desc, ao_distance),
     .min = 0, .max = BIG, .doc = "length of occlusion rays; 0 = unlimited"},
    {.key = "ao_samples", .type = SK_FIELD_INT, .offset = offsetof(sk_render_environment_desc, ao_samples),
     .min = 1, .max = 256, .doc = "occlusion rays per camera sample; default 1"},
};
static const sk_schema environment_schema = {"environment", environment_fields,
                                             sizeof environment_fields / sizeof environment_fields[0]};

static const sk_schema_field image_fields[] = {
    {.key = "width", .type = SK_FIELD_INT, .offset = offsetof(sk_render_image_desc, width), .min = 1,
     .max = SK_RENDER_MAX_DIMENSION, .doc = "pixels; default 640"},
    {.key = "height", .type = SK_FIELD_INT, .offset = offsetof(sk_render_image_desc, height), .min = 1,
     .max = SK_RENDER_MAX_DIMENSION, .doc = "pixels; default 360"},
    {.key = "samples", .type = SK_FIELD_INT, .offset = offsetof(sk_render_image_desc, samples), .min = 1,
     .max = SK_RENDER_MAX_SAMPLES, .doc = "camera samples per pixel; default 16"},
};
static const sk_schema image_schema = {"image", image_fields, sizeof image_fields / sizeof image_fields[0]};

static const sk_schema_field film_fields[] = {
    {.key = "exposure", .type = SK_FIELD_FLOAT, .offset = offsetof(sk_render_film_desc, exposure),
     .min = -30, .max = 30, .doc = "stops; default 0"},
    {.key = "tonemap", .type = SK_FIELD_ENUM, .offset = offsetof(sk_render_film_desc, tonemap),
     .names = sk_render_tonemap_names, .doc = "clamp, reinhard or filmic; default clamp"},
    {.key = "white", .type = SK_FIELD_FLOAT, .offset = offsetof(sk_render_film_desc, white), .min = 0,
     .max = 1e6, .doc = "reinhard: radiance that maps to white; 0 = none"},
    {.key = "opaque", .type = SK_FIELD_BOOL, .offset = offsetof(sk_render_film_desc, opaque),
     .doc = "fill the background with `background`; default false (transparent)"},
    FLOAT3("background", sk_render_film_desc, background, 0, BIG, "background radiance when opaque; default 0"),
};
static const sk_schema film_schema = {"film", film_fields, sizeof film_fields / sizeof film_fields[0]};

/* ---- scene */
static const sk_schema_field scene_fields[] = {
    {.key = "seed", .type = SK_FIELD_SEED, .offset = offsetof(sk_render_scene_desc, seed),
     .doc = "seed of every random sample; default 0"},
    {.key = "unit_mm", .type = SK_FIELD_FLOAT, .offset = offsetof(sk_render_scene_desc, unit_mm),
     .min = 1e-6, .max = 1e9, .doc = "millimetres per scene unit; default 1"},
    {.key = "image", .type = SK_FIELD_OBJECT, .offset = offsetof(sk_render_scene_desc, image),
     .schema = &image_schema, .doc = "size and samples"},
    {.key = "film", .type = SK_FIELD_OBJECT, .offset = offsetof(sk_render_scene_desc, film),
     .schema = &film_schema, .doc = "exposure, tone curve, background"},
    {.key = "camera", .type = SK_FIELD_OBJECT, .offset = offsetof(sk_render_scene_desc, camera),
     .schema = &camera_schema, .doc = "view"},
    {.key = "environment", .type = SK_FIELD_OBJECT, .offset = offsetof(sk_render_scene_desc, environment),
     .schema = &environment_schema, .doc = "ambient light and occlusion"},
    {.key = "materials", .type = SK_FIELD_ARRAY, .offset = offsetof(sk_render_scene_desc, materials),
     .count = SK_RENDER_MAX_MATERIALS, .min_count = 0,
     .count_offset = offsetof(sk_render_scene_desc, material_count),
     .elem_size = sizeof(sk_render_material_desc), .schema = &material_schema, .doc = "materials"},
    {.key = "objects", .type = SK_FIELD_ARRAY, .offset = offsetof(sk_render_scene_desc, objects),
     .count = SK_RENDER_MAX_OBJECTS, .min_count = 0,
     .count_offset = offsetof(sk_render_scene_desc, object_count),
     .elem_size = sizeof(sk_render_object_desc), .schema = &object_schema, .doc = "objects"},
    {.key = "lights", .type = SK_FIELD_ARRAY, .offset = offsetof(sk_render_scene_desc, lights),
     .count = SK_RENDER_MAX_LIGHTS, .min_count = 0,
     .count_offset = offsetof(sk_render_scene_desc, light_count),
     .elem_size = sizeof(sk_render_light_desc), .schema = &light_schema, .doc = "lights"},
};
const sk_schema sk_render_schema = {"scene", scene_fields, sizeof scene_fields / sizeof scene_fields[0]};
