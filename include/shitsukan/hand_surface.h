/* shitsukan hand surface: the skin surface of Yasumuro's thesis (2000, sec. 4.1) on the
 * skeleton of hand_posture.h, its skinning, levels of detail, exports and baked skin
 * texture. */
#ifndef SHITSUKAN_HAND_SURFACE_H
#define SHITSUKAN_HAND_SURFACE_H

#include "shitsukan/gltf.h"
#include "shitsukan/hand_posture.h"
#include "shitsukan/image.h"
#include "shitsukan/mesh.h"
#include "shitsukan/skin.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ============================================================== hand surface */
/* The skin surface of thesis 4.1 built from the skeleton (no scan ships with the
 * thesis): flesh around every link (finger segments, the palm over the metacarpals,
 * thenar and hypothenar pads, webs, the wrist stump, nail plates) with sizes from
 * published anthropometry (presets/hand/flesh.json), blended into one implicit surface
 * and meshed in the relaxed posture into a single closed, manifold triangle mesh; skin
 * weights (the thesis's nearest link, and smooth weights); deformation by rigid links
 * (4.1.5), linear blend or dual quaternion skinning; levels of detail; exports.
 *
 * Thread-safety: a created surface is immutable; every function taking a const surface
 * may run from several threads at once. */

/* Sizes of the flesh in millimetres at the reference hand breadth; widths and
 * thicknesses scale with the skeleton's hand breadth / reference_breadth_mm. */
typedef struct sk_hand_flesh_finger {
    /* Stations along the finger: MCP, PIP, DIP, tip for I..L; MCP, IP, tip (index 0..2)
       for the thumb. Breadth across the palm plane (link X), thickness dorsal-palmar
       (link Z). */
    double breadth_mm[4];
    double thickness_mm[4];
    /* The palm around this finger's metacarpal, at its CMC and MCP ends (thumb: the
       metacarpal inside the thenar). */
    double metacarpal_breadth_mm[2];
    double metacarpal_thickness_mm[2];
} sk_hand_flesh_finger;

/* An ellipsoidal pad in the carpus frame: centre as fractions of hand breadth (x) and
 * length (y) plus mm palmar (z), semi-axes in mm, long axis turned in the palm plane. */
typedef struct sk_hand_flesh_pad {
    double centre_x_hb, centre_y_hl, centre_z_mm;
    double radius_mm[3];
    double angle_deg;
} sk_hand_flesh_pad;

typedef struct sk_hand_flesh {
    double reference_breadth_mm; /* hand breadth of the sizes below (85) */
    sk_hand_flesh_finger finger[SK_HAND_FINGER_COUNT];
    double palm_palmar_shift_mm;                 /* palm flesh centre palmar of the metacarpals */
    double wrist_breadth_mm, wrist_thickness_mm; /* at the wrist crease */
    double stump_length_mm;                      /* forearm kept below the wrist */
    sk_hand_flesh_pad thenar, hypothenar;
    double web_reach; /* webs reach this fraction of the proximal phalanx */
    double web_thickness_mm;
    double thumb_web_thickness_mm;
    double nail_length, nail_breadth; /* fractions of the distal segment / its breadth */
    double nail_thickness_mm;
    double blend_joint_mm, blend_root_mm, blend_palm_mm; /* smooth-union radii */
} sk_hand_flesh;

/* The built-in flesh (the values of presets/hand/flesh.json). */
void sk_hand_flesh_default(sk_hand_flesh *out);
/* Reads a flesh JSON file (format of presets/hand/flesh.json): every key optional,
 * starting from the built-in values. Errors name the key path. */
sk_result sk_hand_flesh_parse(const char *text, size_t length, const char *source_name,
                              sk_hand_flesh *out, sk_error *err);
sk_result sk_hand_flesh_load_file(const char *path, sk_hand_flesh *out, sk_error *err);

typedef struct sk_hand_surface_desc {
    int triangles;              /* target triangle count; 0 = 8000 (the thesis's count);
                                   range [500, 200000] */
    double cell_mm;             /* grid step of the implicit surface's meshing; 0 = chosen
                                   from the hand size and the triangle count; [0.2, 4] */
    const sk_hand_flesh *flesh; /* NULL = sk_hand_flesh_default() */
} sk_hand_surface_desc;

typedef struct sk_hand_surface sk_hand_surface;

/* Builds the flesh around the skeleton in its relaxed posture and meshes it. A left
 * skeleton gives the exact mirror of the right hand's mesh, vertex for vertex (the same
 * vertex order, positions and normals with x negated, triangles wound the other way). */
sk_result sk_hand_surface_create(sk_hand_surface **out, const sk_hand_skeleton *skeleton,
                                 const sk_hand_surface_desc *desc, sk_error *err);
void sk_hand_surface_destroy(sk_hand_surface *surface);
/* The memory sk_hand_surface_create peaks at for the skeleton and desc (bytes; desc may be
 * NULL): the meshing grid's cells near the surface dominate, so it grows with the hand's
 * length x breadth over the grid step squared (measured: 29 MB for the default 8000
 * triangles, 500 MB for 200000). For callers that cap their memory. */
double sk_hand_surface_memory(const sk_hand_skeleton *skeleton, const sk_hand_surface_desc *desc);

/* The closed, manifold mesh in the relaxed posture (positions in mm, unit normals; no
 * UVs: the atlas splits vertices along its seam, see sk_hand_surface_export_mesh), with
 * the attribute "nail" (1 on the nail plates, 0 elsewhere). Owned by the surface. */
const sk_mesh *sk_hand_surface_mesh(const sk_hand_surface *surface);
/* The skeleton it was built on (its relaxed frames are the bind pose). */
const sk_hand_skeleton *sk_hand_surface_skeleton(const sk_hand_surface *surface);

/* The implicit surface in the relaxed posture: negative inside, positive outside, about
 * the signed distance in mm near the surface (exact for a single round segment). */
double sk_hand_surface_field(const sk_hand_surface *surface, sk_vec3d p);
/* Gradient of the field (finite differences of 1e-3 mm). */
sk_vec3d sk_hand_surface_field_gradient(const sk_hand_surface *surface, sk_vec3d p);
/* Signed distance to the implicit surface (negative inside): the point is projected
 * onto the zero set by Newton steps along the gradient; `closest` (may be NULL) gets the
 * surface point. Accurate to about 1e-4 mm within a few mm of the surface. */
double sk_hand_surface_distance(const sk_hand_surface *surface, sk_vec3d p, sk_vec3d *closest);

/* ----------------------------------------------------------- skin weights */
typedef enum sk_hand_weights {
    SK_HAND_WEIGHTS_DEFAULT = 0, /* = SMOOTH */
    SK_HAND_WEIGHTS_NEAREST,     /* the thesis (4.1.5): every vertex on its nearest link */
    SK_HAND_WEIGHTS_SMOOTH       /* falling off along and around the links near joints: at
                                    most 4 links per vertex, summing to 1 */
} sk_hand_weights;

/* 4 links and 4 weights per vertex (vertex_count x 4 each; unused slots have weight 0
 * and link 0; the weights of a vertex sum to 1, largest first). Owned by the surface. */
void sk_hand_surface_weights(const sk_hand_surface *surface, sk_hand_weights which,
                             const uint16_t **links, const float **weights);

/* ------------------------------------------------------------- deformation */
typedef enum sk_hand_skinning {
    SK_HAND_SKINNING_DEFAULT = 0, /* = DQS */
    SK_HAND_SKINNING_RIGID,       /* the thesis: each vertex moves rigidly with its
                                     nearest link */
    SK_HAND_SKINNING_LBS,         /* linear blend of the link transforms, smooth weights */
    SK_HAND_SKINNING_DQS          /* dual quaternion blend (Kavan et al. 2008), smooth
                                     weights: no candy-wrapper collapse under twist */
} sk_hand_skinning;

/* Moves the mesh with posed frames (from sk_hand_forward on the surface's skeleton):
 * writes vertex_count x 3 positions and unit normals (the rest normals turned by each
 * vertex's blended rotation). Allocation-free; one thread below 20000 vertices. */
void sk_hand_surface_deform(const sk_hand_surface *surface, const sk_hand_frames *frames,
                            sk_hand_skinning method, float *positions, float *normals);
/* A posed copy of the mesh (allocated into `out`, free with sk_mesh_free). */
sk_result sk_hand_surface_pose(const sk_hand_surface *surface, const double dofs[SK_HAND_DOF_COUNT],
                               sk_hand_skinning method, sk_mesh *out, sk_error *err);

/* The thesis's defect (4.1.5): on the flexion side the surface sinks into the finger. */
typedef struct sk_hand_defect {
    double rest_volume_mm3, posed_volume_mm3;
    double volume_lost_mm3;     /* rest - posed (signed: negative = volume gained) */
    double volume_lost_percent; /* of the rest volume of the moved links' flesh */
    int inside_count;           /* vertices of a moved link's flesh that end up more than
                                   0.5 mm inside the neighbouring segment's flesh */
    double max_depth_mm;        /* deepest of them */
    int vertex_count;           /* vertices of the moved links (the denominator) */
} sk_hand_defect;
/* Measures the defect of a pose against the relaxed mesh for the links of `finger`. */
sk_result sk_hand_surface_defect(const sk_hand_surface *surface,
                                 const double dofs[SK_HAND_DOF_COUNT], sk_hand_skinning method,
                                 sk_hand_finger finger, sk_hand_defect *out, sk_error *err);

/* ------------------------------------------------------------- levels of detail */
#define SK_HAND_LOD_COUNT 3
/* Triangle targets of the levels: 8000 (level 0, the surface itself), 2000, 500. */
extern const int sk_hand_lod_triangles[SK_HAND_LOD_COUNT];
/* A coarser surface simplified from `base` by meshoptimizer (edge collapses onto its own
 * vertices, so the skin weights carry over unchanged), keeping the field and skeleton. */
sk_result sk_hand_surface_simplify(sk_hand_surface **out, const sk_hand_surface *base,
                                   int target_triangles, sk_error *err);

/* ------------------------------------------------------------- atlas and export */
/* The mesh as renderers and exporters take it: UVs of a two-chart atlas (the back of
 * the hand by planar projection on the left half, seen from the back; the palm on the
 * right half, seen from the palm side, as the thesis maps its photos, 4.1.6), so the
 * vertices along the seam between the charts are split in two. `positions` / `normals`
 * (vertex_count x 3 of the surface mesh, e.g. from sk_hand_surface_deform) or NULL for
 * the relaxed mesh. Adds the attributes "nail" and, if `with_weights`, "joints" and
 * "weights" (4 components each, smooth weights). */
sk_result sk_hand_surface_export_mesh(const sk_hand_surface *surface, const float *positions,
                                      const float *normals, bool with_weights, sk_mesh *out,
                                      sk_error *err);
/* Vertex of the surface mesh behind each export vertex (export vertex count entries). */
const uint32_t *sk_hand_surface_export_map(const sk_hand_surface *surface, size_t *count);

/* ------------------------------------------------------------- glTF export */
/* The skinned hand as glTF 2.0 (include/shitsukan/gltf.h): the skeleton as 20 joint
 * nodes in the link tree, named as the BVH export names them ("Hand", "T_CMC", ...,
 * "L_DIP"), one skin whose inverse bind matrices are the relaxed (bind) pose, one skinned
 * mesh node per level of detail ("hand_LOD0", ...) with JOINTS_0 / WEIGHTS_0, the atlas
 * UVs and the skin material, and optionally the frames as an animation (every joint's
 * rotation and the root's translation, one key per frame at frame / fps seconds, LINEAR).
 *
 * Units and axes: glTF's metres; the hand's frame is kept (X radial, Y distal = glTF's
 * up, Z palmar = glTF's front), so a glTF coordinate is the hand's millimetres / 1000.
 * A joint node's translation is its joint centre in its parent link's frame, its rotation
 * the link frame in the parent's (R_parent^T R_link); the root's are the carpus frame and
 * the wrist centre in the world. */
typedef enum sk_hand_gltf_material {
    SK_HAND_GLTF_MATERIAL_DEFAULT = 0, /* = BLEND */
    SK_HAND_GLTF_MATERIAL_BLEND,       /* the thesis's blend (4.1.6): a white surface lit at
                                          1 - w (base colour, with the normal map) plus the
                                          unlit albedo at w (emissive) */
    SK_HAND_GLTF_MATERIAL_PBR          /* the albedo as base colour, lit (engines' usual
                                          material), with the normal map */
} sk_hand_gltf_material;

typedef struct sk_hand_gltf_desc {
    /* Levels of detail, finest first, all built on one skeleton (a surface and its
       sk_hand_surface_simplify results); each is a mesh node sharing the one skin. */
    const sk_hand_surface *const *lods;
    int lod_count;              /* [1, 8] */
    const double *dofs;         /* frame_count x SK_HAND_DOF_COUNT absolute DOF values */
    int frame_count;            /* [1, 1000000]; more than 1 needs `animation` */
    bool animation;             /* write the frames as an animation (the nodes then stand
                                   in the bind pose); false: the nodes stand in the one
                                   pose given */
    double fps;                 /* key rate of the animation; 0 = 30; (0, 1000] */
    sk_hand_weights weights;    /* 0 = smooth; NEAREST gives every vertex one joint (the
                                   thesis's rigid links) */
    const sk_image *albedo;     /* the atlas's albedo (sk_hand_texture_bake); NULL = a
                                   plain skin colour and no UVs */
    const sk_image *normal_map; /* its normal map; NULL = none (needs albedo) */
    sk_hand_gltf_material material;
    double texture_weight; /* w of the blend; 0 = 0.7 (the thesis's 0.3 : 0.7);
                              [0, 1] */
} sk_hand_gltf_desc;

/* Adds the hand to a document (nodes, skin, meshes, material, animation). Errors name the
 * desc field and its range; nothing is added on an error of the desc. */
sk_result sk_hand_gltf_add(sk_gltf *gltf, const sk_hand_gltf_desc *desc, sk_error *err);
/* The hand alone as one .glb file (atomically written). */
sk_result sk_hand_gltf_write(const sk_hand_gltf_desc *desc, const char *path, sk_error *err);

/* ------------------------------------------------------------- poses, landmarks */
/* Reads a pose file: {"dofs": {"L.MCP.flex": 60, ...}} in degrees (mm for wrist.tx/ty/tz),
 * the format sk_hand_pose_write_json writes (its other keys are accepted); DOFs not given
 * keep their relaxed values. Errors name the key path. */
sk_result sk_hand_pose_parse(const char *text, size_t length, const char *source_name,
                             const sk_hand_skeleton *skeleton, double dofs[SK_HAND_DOF_COUNT],
                             sk_error *err);
sk_result sk_hand_pose_load_file(const char *path, const sk_hand_skeleton *skeleton,
                                 double dofs[SK_HAND_DOF_COUNT], sk_error *err);

/* The 21 landmarks of the common hand-pose datasets (e.g. MediaPipe Hands, FreiHAND):
 * 0 wrist; 1-4 thumb CMC, MCP, IP, tip; 5-8 index MCP, PIP, DIP, tip; 9-12 middle;
 * 13-16 ring; 17-20 little (base to tip). Joint centres of the skeleton, fingertips at
 * the ends of the distal links (where the surface's tips are). */
#define SK_HAND_LANDMARK_COUNT 21
const char *sk_hand_landmark_name(int landmark); /* "wrist", "thumb_cmc", ..., NULL outside */
int sk_hand_landmark_point(int landmark);        /* the skeleton point (sk_hand_point_name) */
/* Per frame (frame_count x SK_HAND_DOF_COUNT dofs): CSV "frame,landmark,name,x_mm,y_mm,z_mm"
 * or JSON {"landmarks": [names], "frames": [[[x, y, z] x 21] per frame]}. */
sk_result sk_hand_landmarks_write(const sk_hand_skeleton *skeleton, const double *dofs,
                                  int frame_count, sk_hand_positions_format format,
                                  const char *path, sk_error *err);

/* ------------------------------------------------------------- appearance */
/* The skin texture of the atlas (sk_hand_surface_export_mesh's UVs), for the thesis's
 * blend of shading and texture (4.1.6, Fig. 4.15: about 0.3 : 0.7). Generated: skin
 * colour (the back a little darker than the palm, knuckles a little redder, nails
 * pink with a pale free edge) and a height field whose normal map carries the skin
 * module's microrelief (back_skin on the back, palm_skin on the palm, evaluated in mm of
 * the planar projection), the transverse creases over the finger joints' backs and the
 * flexion creases of the fingers and the palm. With photos (linear RGB, each covering the
 * rest hand's x-y bounds as seen from its side: the back from the back, the palm from the
 * palm side), their planar projection replaces the generated colour, the two blended
 * across the sides of the hand so the seam does not show. */
typedef struct sk_hand_texture_desc {
    int size;                   /* atlas width = height in pixels; 0 = 1024; [64, 8192] */
    const sk_image *back_photo; /* NULL = generated colour */
    const sk_image *palm_photo;
    const sk_skin *back_skin; /* NULL = no microrelief on the back */
    const sk_skin *palm_skin; /* NULL = none on the palm */
    double relief_scale;      /* multiplies the microrelief's height; 0 = 1; [0, 100] */
    double crease_depth_mm;   /* depth of the joint and palm creases; 0 = 0.25; [0, 5] */
    double seam_width;        /* palm and back blend where |normal.z| < this; 0 = 0.3;
                                 [1e-3, 1] */
} sk_hand_texture_desc;

/* Bakes the albedo (RGB, linear) and the tangent-space normal map (RGB, components
 * 0.5 n + 0.5: write it with SK_PNG_ENCODING_LINEAR) of the atlas. */
sk_result sk_hand_texture_bake(const sk_hand_surface *surface, const sk_hand_texture_desc *desc,
                               sk_image *albedo, sk_image *normal_map, sk_error *err);
/* The memory the bake peaks at (bytes; desc may be NULL): the texels being baked and the
 * two maps, 88 bytes a texel of the atlas (measured: 1.1 GB peak at 4096 x 4096). */
double sk_hand_texture_memory(const sk_hand_texture_desc *desc);

/* Preset schemas (src/models/hand_surface/schema.c) of sk_hand_surface_desc and
 * sk_hand_texture_desc, and the preset names of sk_hand_skinning and sk_hand_gltf_material
 * ("rigid", "lbs", "dqs"; "blend", "pbr"; index = value, NULL-terminated). */
extern const sk_schema sk_hand_surface_schema, sk_hand_texture_schema;
extern const char *const sk_hand_skinning_names[];
extern const char *const sk_hand_gltf_material_names[];

#ifdef __cplusplus
}
#endif

#endif /* SHITSUKAN_HAND_SURFACE_H */
