/* shitsukan renderer: a small, deterministic ray tracer on Embree 3 that shows the other
 * modules' results: triangle meshes (sk_mesh, OBJ/PLY files, built-in primitives with UVs
 * and tangents) as instances, pinhole and orthographic cameras, directional, point and
 * rectangular area lights with shadows, an environment term with optional ambient
 * occlusion, Blinn-Phong materials with image / solid textures, bump and normal maps, the
 * texture/shading blend of the hand thesis (Yasumuro 2000, sec. 4.1.6), skin microrelief
 * (Ishii 1991) as a bump map and the wood solid texture with its figure sheen (Kawai 2000).
 *
 * What it computes (per camera sample): the radiance leaving the first surface hit towards
 * the camera, from direct light (every light, with a shadow ray), plus the environment
 * term. There is no interreflection between surfaces. Radiometric units:
 *   - pixel values: radiance, averaged over the pixel (box filter), linear RGB (sRGB/Rec.709
 *     primaries), in W sr^-1 m^-2 per unit of the lights' `intensity`;
 *   - directional light: `intensity` = irradiance E (W m^-2) on a surface facing it;
 *   - point light: `intensity` = radiant intensity I (W sr^-1), irradiance I cos / d^2;
 *   - rectangular light: `intensity` = emitted radiance Le (W sr^-1 m^-2), one-sided;
 *   - environment: a uniform sky radiance (W sr^-1 m^-2).
 * So a Lambertian surface of albedo rho under a directional light of irradiance E at
 * incidence theta has radiance rho E cos(theta) / pi.
 *
 * Lengths are in scene units; `unit_mm` states how many millimetres one unit is (default 1:
 * scenes are modelled in mm, like the skin and wood modules).
 *
 * Thread-safety: a created sk_render_scene is immutable; sk_render_scene_render and
 * sk_render_scene_intersect may run on one scene from several threads at once. Rendering
 * is parallel itself (OpenMP over tiles) and gives the same bytes for any thread count. */
#ifndef SHITSUKAN_RENDER_H
#define SHITSUKAN_RENDER_H

#include "shitsukan/core.h"
#include "shitsukan/image.h"
#include "shitsukan/io.h"
#include "shitsukan/mesh.h"
#include "shitsukan/preset.h"
#include "shitsukan/skin.h"
#include "shitsukan/wood.h"

#ifdef __cplusplus
extern "C" {
#endif

#define SK_RENDER_MAX_OBJECTS 256
#define SK_RENDER_MAX_MATERIALS 32
#define SK_RENDER_MAX_LIGHTS 16
#define SK_RENDER_NAME_SIZE 32
#define SK_RENDER_PATH_SIZE 256
#define SK_RENDER_MAX_DIMENSION 16384 /* image width / height */
#define SK_RENDER_MAX_SAMPLES 4096    /* samples per pixel */

/* ------------------------------------------------------------------ transforms */

/* object = T(translate) Rz Ry Rx S(scale) local: scale first, then rotations about X, Y
 * and Z (right-handed, radians), then translation. */
typedef struct sk_render_transform {
    float translate[3]; /* scene units; default 0 */
    float rotate[3];    /* Euler angles X, Y, Z in radians (preset key "rotate_deg");
                           default 0 */
    float scale[3];     /* per-axis scale; all 0 = (1, 1, 1); a single 0 is invalid */
} sk_render_transform;

/* ------------------------------------------------------------------ geometry */

typedef enum sk_render_shape {
    SK_RENDER_SHAPE_DEFAULT = 0, /* = MESH */
    SK_RENDER_SHAPE_MESH = 0,    /* "mesh": the `file` (OBJ/PLY) or, from C, `mesh` */
    SK_RENDER_SHAPE_PLANE,       /* "plane": size[0] x size[2] in y = 0, normal +y */
    SK_RENDER_SHAPE_BOX,         /* "box": edge lengths size[0..2], centred */
    SK_RENDER_SHAPE_SPHERE,      /* "sphere": `radius`, centred */
    SK_RENDER_SHAPE_CYLINDER,    /* "cylinder": `radius`, `height` along y, capped, centred */
    SK_RENDER_SHAPE_CAPSULE,     /* "capsule": a cylinder of `height` with hemispherical ends */
    SK_RENDER_SHAPE_COUNT
} sk_render_shape;

/* UVs of the built-in primitives. */
typedef enum sk_render_uv_mode {
    SK_RENDER_UV_DEFAULT = 0, /* = LENGTH */
    SK_RENDER_UV_LENGTH = 0,  /* "length": arc length on the surface in scene units, so a
                                 texture keeps its true size and aspect (u around / across,
                                 v along / up; around a sphere or capsule u is measured at the
                                 equator) */
    SK_RENDER_UV_UNIT,        /* "unit": u, v in [0, 1] over the surface (box: per face) */
    SK_RENDER_UV_COUNT
} sk_render_uv_mode;

typedef struct sk_render_object_desc {
    char name[SK_RENDER_NAME_SIZE];     /* for messages; default "" */
    sk_render_shape shape;              /* preset key "shape"; default "mesh" */
    char file[SK_RENDER_PATH_SIZE];     /* mesh: OBJ or PLY file (relative to the scene file's
                                           folder); meshes without normals are shaded flat,
                                           meshes without UVs get u = v = 0 */
    const sk_mesh *mesh;                /* C API only: the caller's mesh (used by shape "mesh"
                                           when `file` is empty; copied at scene creation) */
    float size[3];                      /* box: edge lengths; plane: size[0] along x, size[2]
                                           along z; all 0 = (1, 1, 1) */
    float radius;                       /* sphere, cylinder, capsule; 0 = 0.5 */
    float height;                       /* cylinder, capsule: length of the straight part along
                                           y; 0 = 1 */
    int segments;                       /* tessellation around the y axis; 0 = 64; [3, 4096] */
    int rings;                          /* tessellation from pole to pole (sphere, capsule caps);
                                           0 = 32; [2, 4096] */
    sk_render_uv_mode uv;               /* preset key "uv": "length" or "unit"; default length */
    char material[SK_RENDER_NAME_SIZE]; /* name of a material; "" = a grey diffuse default */
    sk_render_transform transform;
} sk_render_object_desc;

/* ------------------------------------------------------------------ camera */

typedef enum sk_render_projection {
    SK_RENDER_PROJECTION_DEFAULT = 0,     /* = PERSPECTIVE */
    SK_RENDER_PROJECTION_PERSPECTIVE = 0, /* "perspective": pinhole */
    SK_RENDER_PROJECTION_ORTHOGRAPHIC,    /* "orthographic": parallel rays */
    SK_RENDER_PROJECTION_COUNT
} sk_render_projection;

/* Position and target both all 0 (the default) frames the whole scene: the camera looks
 * along -z at the centre of the scene's bounding sphere from where that sphere fills the
 * view (perspective) or sets the view height to its diameter (orthographic). */
typedef struct sk_render_camera_desc {
    sk_render_projection projection; /* preset key "projection" */
    float position[3];               /* eye point; see above */
    float target[3];                 /* point looked at (the image centre) */
    float up[3];                     /* a direction that is up in the image; all 0 = +y */
    float fov;          /* perspective: vertical field of view in radians (key "fov_deg");
                           0 = 40 degrees; [0.001, 179] degrees */
    float ortho_height; /* orthographic: height of the view in scene units; 0 = what the
                           perspective fov sees at the target's distance */
} sk_render_camera_desc;

/* ------------------------------------------------------------------ lights */

typedef enum sk_render_light_type {
    SK_RENDER_LIGHT_DEFAULT = 0,     /* = DIRECTIONAL */
    SK_RENDER_LIGHT_DIRECTIONAL = 0, /* "directional": parallel light (sun) */
    SK_RENDER_LIGHT_POINT,           /* "point" */
    SK_RENDER_LIGHT_RECT,            /* "rect": one-sided rectangle, soft shadows */
    SK_RENDER_LIGHT_SPHERE,          /* "sphere": a sphere emitting from its whole surface */
    SK_RENDER_LIGHT_DISC,            /* "disc": one-sided disc */
    SK_RENDER_LIGHT_COUNT
} sk_render_light_type;

/* `intensity` 0 means: the value that gives a surface at the camera target facing the
 * light an irradiance of pi (so a white Lambertian surface there has radiance 1 and shows
 * as white at exposure 0): E = pi (directional), I = pi d^2 (point), Le = pi d^2 / area
 * (rect), Le = d^2 / radius^2 (sphere, disc), d = distance from the light to the camera
 * target. Area lights (rect, sphere, disc) are not scene geometry: they cast no shadows on
 * each other, and the path integrator's camera and bounce rays see their radiance. */
typedef struct sk_render_light_desc {
    sk_render_light_type type; /* preset key "type" */
    float color[3];            /* linear RGB tint multiplying `intensity`; all 0 = (1, 1, 1) */
    float intensity;           /* E (W m^-2), I (W sr^-1) or Le (W sr^-1 m^-2) by type; see above */
    float position[3];         /* point: the light; rect: the rectangle's centre */
    float direction[3];        /* directional: the direction the light travels; all 0 = (0, -1, 0);
                                  rect: the direction it emits towards; all 0 = towards the camera
                                  target */
    float size[2];             /* rect: width and height in scene units; all 0 = (1, 1) */
    float radius;              /* sphere, disc: radius in scene units; 0 = 0.5 */
    float up[3];               /* rect: the direction of its height edge (projected on its plane);
                                  all 0 = +y (or +z when it faces along y) */
    int samples;               /* rect, sphere, disc: shadow rays per camera sample (preview
                                  integrator; the path integrator takes one per vertex);
                                  0 = 1; [1, 256] */
    bool no_shadows;           /* skip shadow rays; default false */
} sk_render_light_desc;

/* Uniform environment radiance lights every point from the whole sphere. Without
 * ambient occlusion a surface of diffuse albedo rho gets rho L_env (the environment
 * integrated over its unoccluded hemisphere); with it, that term is weighted by the
 * fraction of cosine-weighted rays that escape within `ao_distance`, which is the exact
 * one-bounce environment light when the blocker is black. The Blinn-Phong lobe gets
 * ks L_env (its directional albedo) times the same visibility. */
typedef enum sk_render_environment_type {
    SK_RENDER_ENVIRONMENT_DEFAULT = 0, /* = UNIFORM */
    SK_RENDER_ENVIRONMENT_UNIFORM = 0, /* "uniform": `radiance` from every direction */
    SK_RENDER_ENVIRONMENT_MAP,         /* "map": a lat-long EXR image (`map`) */
    SK_RENDER_ENVIRONMENT_SKY,         /* "sky": a procedural gradient sky with a sun */
    SK_RENDER_ENVIRONMENT_COUNT
} sk_render_environment_type;

/* The lat-long map's centre column looks along -z, its top row is +y; `rotate` turns it
 * about +y. The sky is a gradient (ground below the horizon, horizon to zenith above) plus
 * a sun disc. Both are importance sampled by the path integrator; the preview integrator
 * lights with their mean radiance as a uniform environment. */
typedef struct sk_render_environment_desc {
    sk_render_environment_type type; /* preset key "type"; default uniform */
    float radiance[3];               /* uniform: linear RGB; default 0 (no environment light) */
    bool ambient_occlusion;          /* trace occlusion rays; default false */
    float ao_distance;               /* length of occlusion rays in scene units; 0 = unlimited */
    int ao_samples;                  /* occlusion rays per camera sample; 0 = 1; [1, 256] */
    char map[SK_RENDER_PATH_SIZE];   /* map: lat-long EXR file, relative to the scene file */
    float strength;                  /* map, sky: multiplies the radiance; 0 = 1; [0, 1e9] */
    float rotate;                    /* map: turn about +y in radians (key "rotate_deg") */
    float sun_direction[3];          /* sky: towards the sun; all 0 = (0.4, 0.7, 0.3) */
    float sun_irradiance;            /* sky: irradiance of the sun disc; 0 = 5 W m^-2 */
    float sun_size;                  /* sky: angular diameter in radians (key "sun_size_deg");
                                        0 = 3 degrees; [0.5, 45] degrees */
    float zenith[3];                 /* sky: radiance at the zenith; all 0 = (0.2, 0.35, 0.8) */
    float horizon[3];                /* sky: radiance at the horizon; all 0 = (0.8, 0.85, 0.9) */
    float ground[3]; /* sky: radiance below the horizon; all 0 = (0.2, 0.18, 0.16) */
} sk_render_environment_desc;

/* ------------------------------------------------------------------ materials */

typedef enum sk_render_material_type {
    SK_RENDER_MATERIAL_DEFAULT = 0,  /* = STANDARD */
    SK_RENDER_MATERIAL_STANDARD = 0, /* "standard": diffuse + Blinn-Phong */
    SK_RENDER_MATERIAL_SKIN,         /* "skin": standard, bump-mapped by the skin microrelief
                                        (Ishii 1991) evaluated at st in mm */
    SK_RENDER_MATERIAL_WOOD,         /* "wood": the wood solid texture (Kawai 2000) at the
                                        object-frame point in mm, with its reflection model */
    SK_RENDER_MATERIAL_TYPE_COUNT
} sk_render_material_type;

/* One "key.path=value" edit of a referenced preset (as with --set on the command line). */
#define SK_RENDER_MAX_PRESET_SETS 8
typedef struct sk_render_preset_set {
    char text[128];
} sk_render_preset_set;

/* A shading point as a texture callback sees it. Vectors are unit length, in the scene
 * frame unless named `object_`. */
typedef struct sk_render_surface {
    sk_vec3f point;         /* scene position */
    sk_vec3f object_point;  /* position in the object's frame: the object's translation and
                               rotation undone, its scale kept (true scene lengths), so a
                               solid texture moves with the object */
    sk_vec3f normal;        /* interpolated normal, facing the viewer */
    sk_vec3f object_normal; /* the same in the object's frame */
    sk_vec3f tangent;       /* along increasing u (orthogonal to `normal`) */
    sk_vec3f bitangent;     /* along increasing v */
    sk_vec2f uv;            /* the mesh's UV */
    sk_vec2f st;            /* texture coordinates: uv * uv_scale + uv_offset */
    sk_vec2f st_per_mm;     /* how fast s and t change per mm of surface along tangent and
                               bitangent (converts st-space slopes to surface slopes) */
    float footprint_mm;     /* width of one camera sample's footprint on the surface */
    int object;             /* index of the object in the scene desc */
} sk_render_surface;

/* What a texture callback may change. On entry: the material's constant values. */
typedef struct sk_render_texel {
    sk_vec3f albedo; /* linear diffuse reflectance in [0, 1] */
    float specular;  /* ks in [0, 1] */
    float shininess; /* Blinn-Phong exponent */
    sk_vec2f slope;  /* height gradient dh/ds, dh/dt with h in mm and (s, t) the texture
                        coordinates (bump mapping); on entry 0 */
} sk_render_texel;

/* A procedural texture: called at every shading point (from several threads at once; it
 * must be thread-safe and should not allocate). Supplies solid textures (3D point ->
 * albedo) and height fields (bump mapping) from C. */
typedef void (*sk_render_texture_fn)(void *user, const sk_render_surface *surface,
                                     sk_render_texel *texel);

typedef struct sk_render_material_desc {
    char name[SK_RENDER_NAME_SIZE]; /* objects refer to it by this; must be unique */
    sk_render_material_type type;   /* preset key "type" */
    float albedo[3]; /* linear diffuse reflectance; all 0 = (0.8, 0.8, 0.8); [0, 1] */
    char albedo_texture[SK_RENDER_PATH_SIZE]; /* image (PNG decoded from sRGB, or EXR)
                                                 multiplying `albedo`, one repeat per unit
                                                 of st, bilinear; default none */
    float specular;  /* ks: weight of the Blinn-Phong lobe (the diffuse part gets
                        1 - ks); default 0; [0, 1] */
    float shininess; /* Blinn-Phong exponent n; 0 = 64; [1, 100000] */
    char normal_map[SK_RENDER_PATH_SIZE]; /* tangent-space normal map (PNG read linearly or
                                             EXR; x right = +u, y up = +v, OpenGL style) */
    float bump_scale;   /* multiplies every height gradient (bump / skin / callback and
                           the normal map's tilt); 0 = 1; [0, 100] */
    float uv_scale[2];  /* st = uv * uv_scale + uv_offset; all 0 = (1, 1) */
    float uv_offset[2]; /* default 0 */
    /* The hand thesis (Yasumuro 2000, sec. 4.1.6, Fig. 4.15) renders skin as a blend of
       smooth shading of a white surface and the unlit texture, about 0.3 : 0.7. With
       texture_weight w > 0 the radiance is (1 - w) L(white albedo) + w albedo
       texture_radiance. */
    float texture_weight;   /* w; default 0 (off: albedo multiplies the shading); [0, 1] */
    float texture_radiance; /* radiance of an albedo of 1 in the blend; 0 = 1 */
    /* skin: sk_skin_eval(st.x, st.y) in mm gives the height gradient of the bump map, so
       with the built-in primitives' length UVs in a scene in mm (uv_scale 1) the relief has
       its true size on the surface and stays sharp at any distance. */
    char skin_preset[SK_RENDER_PATH_SIZE]; /* a shipped skin preset ("fig19f") or a JSON file
                                              relative to the scene; resolved into `skin` by
                                              sk_render_scene_desc_bind */
    int skin_set_count;
    sk_render_preset_set skin_set[SK_RENDER_MAX_PRESET_SETS]; /* edits of skin_preset */
    sk_skin_desc skin; /* the skin (preset key "skin"; used as is from C) */
    /* wood: sk_wood_eval at the point in the object's frame (in mm) gives the albedo (rings,
       fibre streaks, vessels) that replaces `albedo`, and sk_wood_shade the reflection: the
       figure sheen of eq. (4) (diffuse on the true normal, specular on the normal tilted by
       the fibre's dive angle) or the 3D fibre highlight, by the wood's shading model (so
       `specular` and `shininess` are not used). The environment lights its diffuse part. */
    char wood_preset[SK_RENDER_PATH_SIZE]; /* a shipped wood preset ("fig9", "oak") or a JSON
                                              file relative to the scene */
    int wood_set_count;
    sk_render_preset_set wood_set[SK_RENDER_MAX_PRESET_SETS]; /* edits of wood_preset */
    sk_wood_desc wood; /* the wood (preset key "wood"; used as is from C) */
    /* C API only: a procedural texture applied after the image textures. */
    sk_render_texture_fn texture;
    void *texture_user;
    /* C API only: things built once and shared by scenes made again and again (e.g. one
       scene per animation frame). They are referenced, not copied: they must outlive
       every scene made from the desc.
       - wood_tree: a tree from sk_wood_create used instead of building one from `wood`
         (type wood; `wood` is then not used);
       - albedo_image / normal_image: linear images (1-4 channels) used instead of the
         albedo_texture / normal_map files (a normal map holds 0.5 n + 0.5). */
    const sk_wood *wood_tree;
    const sk_image *albedo_image;
    const sk_image *normal_image;
} sk_render_material_desc;

/* ------------------------------------------------------------------ image and film */

typedef enum sk_render_tonemap_mode {
    SK_RENDER_TONEMAP_DEFAULT = 0, /* = CLAMP */
    SK_RENDER_TONEMAP_CLAMP = 0,   /* "clamp": display = min(exposed radiance, 1) */
    SK_RENDER_TONEMAP_REINHARD,    /* "reinhard": on luminance, L (1 + L / W^2) / (1 + L)
                                      with W = `white` (Reinhard et al. 2002, eq. 4) */
    SK_RENDER_TONEMAP_FILMIC,      /* "filmic": per channel, the ACES filmic curve fit of
                                      Narkowicz 2015 */
    SK_RENDER_TONEMAP_COUNT
} sk_render_tonemap_mode;

typedef struct sk_render_image_desc {
    int width;   /* pixels; 0 = 640; [1, 16384] */
    int height;  /* pixels; 0 = 360; [1, 16384] */
    int samples; /* camera samples per pixel (stratified, multi-jittered); 0 = 16;
                    [1, 4096] */
} sk_render_image_desc;

/* From linear radiance to the PNG: radiance * 2^exposure -> tone curve -> sRGB transfer
 * curve (applied by the PNG writer) -> 8 bits. The EXR keeps the linear radiance. */
typedef enum sk_render_integrator {
    SK_RENDER_INTEGRATOR_DEFAULT = 0, /* = PREVIEW */
    SK_RENDER_INTEGRATOR_PREVIEW = 0, /* "preview": direct light + uniform environment / AO */
    SK_RENDER_INTEGRATOR_PATH,        /* "path": unidirectional path tracing with next-event
                                         estimation and multiple importance sampling */
    SK_RENDER_INTEGRATOR_PATH_BSDF,   /* "path_bsdf": path tracing by BSDF sampling alone
                                         (area lights and the environment found by chance; a
                                         reference for "path") */
    SK_RENDER_INTEGRATOR_COUNT
} sk_render_integrator;

typedef struct sk_render_film_desc {
    float exposure;                  /* stops; default 0; [-30, 30] */
    sk_render_tonemap_mode tonemap;  /* preset key "tonemap"; default clamp */
    float white;                     /* reinhard: exposed radiance that maps to white; 0 = no
                                        white point (L / (1 + L)); [0, 1e6] */
    bool opaque;                     /* true: `background` fills the background with alpha 1;
                                        default false: the background is transparent (alpha 0;
                                        the EXR holds premultiplied RGBA) */
    float background[3];             /* radiance behind the objects when opaque; default 0 */
    sk_render_integrator integrator; /* preset key "integrator"; default preview */
    int max_bounces; /* path: surface scatterings per path (1 = direct light only); 0 = 8;
                        [1, 1024] */
} sk_render_film_desc;

/* ------------------------------------------------------------------ scene */

typedef struct sk_render_scene_desc {
    uint64_t seed; /* every random sample derives from hash(seed, pixel, sample, use);
                      default 0 */
    float unit_mm; /* millimetres per scene unit; 0 = 1; [1e-6, 1e9] */
    sk_render_image_desc image;
    sk_render_film_desc film;
    sk_render_camera_desc camera;
    sk_render_environment_desc environment;
    int material_count; /* default 0 */
    sk_render_material_desc materials[SK_RENDER_MAX_MATERIALS];
    int object_count; /* default 0 (an empty scene renders the background) */
    sk_render_object_desc objects[SK_RENDER_MAX_OBJECTS];
    int light_count; /* default 0 */
    sk_render_light_desc lights[SK_RENDER_MAX_LIGHTS];
    /* C API only: the folder relative file names are resolved against; "" = the current
       folder. sk_render_scene_desc_load sets it to the scene file's folder. */
    char base_dir[SK_RENDER_PATH_SIZE];
} sk_render_scene_desc;

/* Writes the desc with zero defaults filled in to `out` (which may be `desc` itself; the
 * desc is large, so it is not returned by value). Camera framing and light intensities
 * stay as given: they need the geometry and are resolved by sk_render_scene_create (see
 * sk_render_scene_get_desc). */
void sk_render_scene_desc_resolve(const sk_render_scene_desc *desc, sk_render_scene_desc *out);

/* Checks ranges, NaN and the rules the schema cannot state (unique material names,
 * objects naming existing materials, a camera that is not degenerate). Messages name the
 * key path, e.g. "objects[2].material = \"skn\" is not a material of the scene (materials:
 * skin, floor)". */
sk_result sk_render_scene_desc_validate(const sk_render_scene_desc *desc, sk_error *err);

/* Preset schema of sk_render_scene_desc (key paths as in the field comments). */
extern const sk_schema sk_render_schema;

/* Finds a shipped preset file of another module ("skin", "wood") by name. */
typedef bool (*sk_render_find_preset_fn)(void *user, const char *module, const char *name,
                                         char *path, size_t size);

typedef struct sk_render_load_desc {
    const char *scene_path; /* the scene file (its folder resolves relative file names);
                               NULL = current folder */
    /* Looks up "skin_preset" / "wood_preset" names; NULL = <scene folder>/../<module>/
       <name>.json (the layout of the shipped presets folder). A name containing '/' or
       ending in ".json" is always a file path relative to the scene file. */
    sk_render_find_preset_fn find_preset;
    void *find_preset_user;
} sk_render_load_desc;

/* Binds a scene JSON tree (after any --set edits) onto a zeroed desc: the schema binding,
 * then material presets, then validation. `desc` is large (allocate it on the heap). */
sk_result sk_render_scene_desc_bind(const sk_preset *scene, const sk_render_load_desc *load,
                                    sk_render_scene_desc *desc, sk_error *err);
/* Reads, binds and validates a scene file. */
sk_result sk_render_scene_desc_load(const char *path, sk_render_scene_desc *desc, sk_error *err);

/* ------------------------------------------------------------------ scene objects */

typedef struct sk_render_scene sk_render_scene;

/* About how many bytes sk_render_scene_create and the render will need (an upper bound
 * from the objects' tessellation, mesh file sizes and the image size), for refusing a
 * scene before building it. *largest_object (if not NULL) is the object that needs the
 * most, to name in a message. Skin and wood materials are not counted. */
double sk_render_scene_desc_memory(const sk_render_scene_desc *desc, int *largest_object);

/* Builds the scene: meshes (files read, primitives tessellated, tangents computed),
 * textures, materials' solid textures and the Embree acceleration structure. Errors name
 * the key path (e.g. "objects[1].file = \"arm.obj\": ..."). */
sk_result sk_render_scene_create(const sk_render_scene_desc *desc, sk_render_scene **out,
                                 sk_error *err);
void sk_render_scene_destroy(sk_render_scene *scene);

/* The resolved desc the scene was built from (camera framing resolved too). */
const sk_render_scene_desc *sk_render_scene_get_desc(const sk_render_scene *scene);

/* Scene bounds in scene units; false for a scene without geometry. */
bool sk_render_scene_bounds(const sk_render_scene *scene, sk_vec3f *lo, sk_vec3f *hi);

/* The first surface a ray hits (ray queries for tools and tests). */
typedef struct sk_render_hit {
    bool hit;
    float distance;            /* ray parameter t of the hit (direction need not be unit) */
    sk_vec3f point;            /* scene position */
    sk_vec3f normal;           /* interpolated unit normal, as the mesh winds (not flipped) */
    sk_vec3f geometric_normal; /* unit normal of the triangle's plane, as it winds */
    sk_vec3f tangent;          /* unit, along increasing u */
    sk_vec2f uv;
    int object;        /* index into the desc's objects */
    uint32_t triangle; /* triangle index in the object's mesh */
} sk_render_hit;

void sk_render_scene_intersect(const sk_render_scene *scene, sk_vec3f origin, sk_vec3f direction,
                               float max_distance, sk_render_hit *hit);

/* ------------------------------------------------------------------ rendering */

typedef struct sk_render_stats {
    double seconds; /* wall time of the render */
    long long camera_rays;
    long long shadow_rays; /* light and occlusion rays */
    double camera_rays_per_second;
    /* with sk_render_options.timing: thread-seconds spent inside Embree (closest-hit and
       occlusion queries) and in everything else per sample (camera, materials, skin and
       wood evaluation, light sampling, film) */
    double intersect_seconds;
    double shade_seconds;
} sk_render_stats;

typedef struct sk_render_options {
    sk_progress progress; /* fraction of tiles done */
    bool timing;          /* measure intersection vs shading time (costs a few percent) */
    int tile_size;        /* pixels per side of the tiles threads take; 0 = 16; the image does
                             not depend on it */
} sk_render_options;

/* Renders the scene into `image` (allocated here: RGBA float, width x height of the desc's
 * image): RGB = linear radiance premultiplied by alpha, A = fraction of the pixel covered
 * by geometry (1 everywhere when the film is opaque). `options` and `stats` may be NULL. */
sk_result sk_render_scene_render(const sk_render_scene *scene, const sk_render_options *options,
                                 sk_image *image, sk_render_stats *stats, sk_error *err);

/* Display values of a rendered image: un-premultiplies, applies exposure and the tone
 * curve and clamps to [0, 1] (still linear: the PNG writer applies the sRGB curve). */
sk_result sk_render_tonemap(const sk_image *linear, const sk_render_film_desc *film,
                            sk_image *display, sk_error *err);

/* Writes a rendered image by extension: ".exr" linear RGBA float (premultiplied), ".png"
 * tone-mapped 8-bit sRGB RGBA. `metadata` may be NULL. */
sk_result sk_render_write(const sk_image *linear, const sk_render_film_desc *film, const char *path,
                          const sk_image_metadata *metadata, sk_error *err);

/* ------------------------------------------------------------------ export */

/* The scene's geometry for other tools: every object's mesh (primitives tessellated as the
 * renderer tessellates them, meshes as loaded) with its material approximated (glTF
 * metallic-roughness, metallic 0, double-sided as the renderer shades both sides):
 *   - standard: base colour (1 - specular) albedo, times its albedo texture (embedded, with
 *     the material's uv_scale / uv_offset applied to the uvs); roughness from the
 *     Blinn-Phong exponent, (2 / (n + 2))^(1/4), or 1 without specular; its normal map;
 *   - skin: base colour (1 - specular) albedo (an albedo texture joins as its mean); the
 *     microrelief as a normal texture of one skin tile (texture_size pixels square),
 *     repeated by uvs of st / tile size (periodic skins only), normal scale = bump_scale;
 *   - wood: its albedo times its diffuse weight baked into a base colour texture over an
 *     atlas of the object (runs of triangles laid flat at their true size, so the mesh is
 *     unwelded and its uvs are the atlas's; texels coarser than 0.25 mm average 2 x 2
 *     samples), the largest wood object texture_size pixels square, the others at the
 *     same texels per mm (powers of two, at least 64); with no_textures, or when an object
 *     has too many triangles for its atlas, the mean albedo over the surface instead;
 *     roughness from the wood's specular exponent.
 * A base colour texture holds the whole colour (its factor is 1). Not carried over: the
 * figure sheen, the texture/shading blend, procedural texture callbacks, vertex colours,
 * lights and cameras.
 *
 * ".glb": one node per object with its transform as translation / rotation / scale, under
 * a root node "scene" scaling scene units to metres (unit_mm / 1000); objects with the
 * same mesh and material share one glTF mesh. ".obj": one OBJ object per scene object,
 * transforms applied to the vertices, in metres, an MTL file beside it with each
 * material's Kd (linear, as Blender reads it) and map_Kd, the base colour textures as sRGB
 * PNG files beside it ("<obj name>-<material>.png"); normal maps are not written to OBJ.
 * Material names are made distinct. */
typedef struct sk_render_export_desc {
    int texture_size;     /* pixels per side of the skin tile and of the largest wood
                             object's texture; 0 = 1024; [16, 8192] */
    bool no_textures;     /* bake nothing: wood gets its mean albedo, skin no normal map */
    sk_progress progress; /* fraction of the baking done */
    /* NULL: the export's files (the .glb; or the .obj, its .mtl and textures) appear all
       together or none. Given: they are reserved in this set and written under its staged
       names, and appear when the caller commits it (with the run's other outputs). */
    sk_output_set *outputs;
} sk_render_export_desc;

/* Writes the export by the path's extension (.glb or .obj; all files or none, each
 * atomically). The output paths are checked before the baking. `desc` may be NULL. */
sk_result sk_render_scene_export(const sk_render_scene *scene, const char *path,
                                 const sk_render_export_desc *desc, sk_error *err);
/* The memory the export peaks at beyond the scene's (bytes): the meshes copied, and the
 * textures baked at texture_size (12 bytes a texel, 20 while the wood is baked). */
double sk_render_scene_export_memory(const sk_render_scene *scene,
                                     const sk_render_export_desc *desc);

/* ------------------------------------------------------------------ primitives */

/* The built-in primitives as meshes: positions, normals, UVs and a 4-component "tangent"
 * attribute (xyz along increasing u, w = +-1 with bitangent = w cross(normal, tangent)).
 * `object` gives shape, sizes, tessellation and UV mode (its transform is not applied). */
sk_result sk_render_make_primitive(const sk_render_object_desc *object, sk_mesh *mesh,
                                   sk_error *err);

/* Deprecated (kept for one release; docs/architecture.md): the old name of
 * sk_mesh_compute_tangents, which include/shitsukan/mesh.h declares with the normals. */
sk_result sk_render_compute_tangents(sk_mesh *mesh, sk_error *err);

/* Names of the enums as used in scene files. */
extern const char *const sk_render_shape_names[];
extern const char *const sk_render_uv_mode_names[];
extern const char *const sk_render_projection_names[];
extern const char *const sk_render_light_type_names[];
extern const char *const sk_render_material_type_names[];
extern const char *const sk_render_tonemap_names[];
extern const char *const sk_render_integrator_names[];
extern const char *const sk_render_environment_type_names[];

#ifdef __cplusplus
}
#endif

#endif /* SHITSUKAN_RENDER_H */
