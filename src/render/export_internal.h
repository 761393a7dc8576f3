/* Private structures of the scene export (render.h, sk_render_scene_export): the scene's
 * objects as meshes and approximated materials, ready for the glTF and OBJ writers. */
#ifndef SK_RENDER_EXPORT_INTERNAL_H
#define SK_RENDER_EXPORT_INTERNAL_H

#include "render/render_internal.h"

#define SK__EXPORT_NAME_SIZE (2 * SK_RENDER_NAME_SIZE + 16)

/* A material as other tools can take it: glTF metallic-roughness (metallic 0). */
typedef struct sk__export_material {
    char name[SK__EXPORT_NAME_SIZE];
    float base_color[3]; /* linear, multiplies the texture */
    float roughness;
    sk_image base_texture;   /* linear RGB in [0, 1], or data NULL */
    sk_image normal_texture; /* tangent-space RGB components in [-1, 1], or data NULL */
    float normal_scale;
} sk__export_material;

/* A mesh as written: a copy of the scene mesh with uvs in the frame its material's
 * textures use (or an atlas), tangents kept for a normal texture; bottom-left uv origin. */
typedef struct sk__export_mesh {
    char name[SK__EXPORT_NAME_SIZE];
    sk_mesh mesh;
    int material;   /* index into the export's materials */
    int scene_mesh; /* the scene mesh it came from */
    int scene_material;
    bool per_object; /* baked for one object alone (not shared) */
} sk__export_mesh;

typedef struct sk__export {
    sk__export_material *materials;
    int material_count;
    sk__export_mesh *meshes;
    int mesh_count;
    int object_mesh[SK_RENDER_MAX_OBJECTS]; /* the export mesh of each object */
    int object_count;
} sk__export;

/* ---- export.c */
sk_result sk__export_build(const sk_render_scene *scene, const sk_render_export_desc *desc,
                           sk__export *out, sk_error *err);
void sk__export_free(sk__export *e);
/* The object's name for files and tools: its own, or "object<i>". */
void sk__export_object_name(const sk_render_scene *scene, int object, char *out, size_t size);

/* ---- export_material.c: approximations of the renderer's materials */
/* Fills `out` for scene material `index`; textures only when `textures` (texture_size px
   for the skin's normal tile). Wood materials get their factors here and their texture
   from the bake. */
sk_result sk__export_material_make(const sk_render_scene *scene, int index, bool textures,
                                   int texture_size, sk__export_material *out, sk_error *err);
void sk__export_material_free(sk__export_material *m);
/* Multiplies the base colour factor into the base colour texture (factor 1 after): MTL
   readers differ on whether Kd multiplies map_Kd (Blender's does not), glTF's always. */
void sk__export_material_fold_factor(sk__export_material *m);
/* The affine map uv -> scale * uv + offset to the uvs the material's textures read:
   st = uv * uv_scale + uv_offset, divided by the skin tile (mm) for a skin normal texture;
   the identity for a material without textures (the mesh keeps its own uvs). */
void sk__export_material_uv_frame(const sk_render_scene *scene, int index, bool textures,
                                  float scale[2], float offset[2]);
/* Roughness of a Blinn-Phong lobe of weight ks and exponent n: (2 / (n + 2))^(1/4), the
   perceptual roughness whose GGX / Beckmann width alpha^2 = 2 / (n + 2) matches it; 1
   without a lobe. */
float sk__export_roughness(float ks, float n);

/* ---- export_bake.c: the wood's solid texture as a base colour texture */
/* The object's mesh unwelded onto a per-triangle atlas (two triangles per square cell)
   and its wood albedo baked into a size x size RGB image. SK_ERROR_LIMIT when the cells
   would be smaller than 4 texels. */
sk_result sk__export_bake_wood(const sk_render_scene *scene, int object, int size, sk_mesh *mesh,
                               sk_image *albedo, sk_error *err);
/* The object's surface area in mm^2 (its scale applied). */
double sk__export_surface_mm2(const sk_render_scene *scene, int object);
/* The wood's albedo averaged over the object's surface (area-weighted, 4 points per
   triangle). */
sk_vec3f sk__export_wood_mean(const sk_render_scene *scene, int object);

/* ---- writers */
sk_result sk__export_write_glb(const sk_render_scene *scene, const sk__export *e, const char *path,
                               sk_error *err);
/* The OBJ export's files in an output set: the OBJ and its MTL reserved (final and staged
   names), the textures reserved by the writer beside the OBJ. */
typedef struct sk__export_files {
    sk_output_set *set;
    const char *path, *staged;    /* the .obj */
    const char *mtl, *staged_mtl; /* its .mtl */
} sk__export_files;
sk_result sk__export_write_obj(const sk_render_scene *scene, const sk__export *e,
                               const sk__export_files *files, sk_error *err);

#endif
