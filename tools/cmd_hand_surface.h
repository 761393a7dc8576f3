/* Helpers shared by the hand surface commands (`hand mesh`, and the surface outputs of
 * `hand animate`): argument parsing, the memory and files checked before the work, and the
 * calls into the library. */
#ifndef SK_TOOLS_CMD_HAND_SURFACE_H
#define SK_TOOLS_CMD_HAND_SURFACE_H

#include <limits.h>

#include "cli.h"
#include "hand_params.h"
#include "shitsukan/hand.h"
#include "shitsukan/io.h"

/* The surface's keys and options, every one checked before any work: surface.*,
 * texture.*, skinning, material (hand_params.h; --triangles, --texture-size, --skinning,
 * --material), --flesh (read now), --texture's file names. */
typedef struct hand_surface_plan {
    sk_hand_surface_desc desc; /* resolved: the stated defaults */
    sk_hand_flesh flesh;
    sk_hand_skinning method;                 /* resolved */
    sk_hand_gltf_material material;          /* resolved */
    sk_hand_texture_desc texture;            /* the bake's size and relief (resolved; no skins) */
    const char *prefix;                      /* --texture PREFIX, or NULL */
    char albedo[PATH_MAX], normal[PATH_MAX]; /* its files' final names */
    const char *albedo_out, *normal_out;     /* where they are written (staged, once reserved) */
    char mtl[PATH_MAX];                      /* a textured OBJ's MTL: final name ... */
    const char *mtl_out;                     /* ... and where it is written */
} hand_surface_plan;
int hand_surface_plan_parse(const cli_command *cmd, const cli_args *args, const hand_params *params,
                            hand_surface_plan *plan);
/* Refuses (exit 2, naming --triangles and --texture-size) a plan whose surface, its levels
 * of detail (lod_count) and, when `bake`, its texture need more than --max-memory. */
int hand_surface_plan_check_memory(const cli_args *args, const hand_surface_plan *plan,
                                   const sk_hand_skeleton *skel, bool bake, int lod_count);
/* Reserves --texture's two PNGs (when given) and, for `obj` (the OBJ's final path; NULL =
 * none) textured, its MTL, in `set`. */
int hand_surface_plan_reserve(hand_surface_plan *plan, sk_output_set *set, const char *obj);

/* A shipped skin preset (presets/skin/NAME.json) built into a skin; prints the error and
 * returns its status when it is missing or bad. */
int hand_load_skin(const char *name, sk_skin **out);
/* The surface of the skeleton at level of detail `lod`. */
int hand_build_surface(const hand_surface_plan *plan, const sk_hand_skeleton *skel, int lod,
                       sk_hand_surface **out);
/* One pose as OBJ or PLY (by extension) at `path` (a staged name: the MTL goes to the
 * plan's mtl_out), with --texture's maps. */
int hand_write_posed_mesh(const hand_surface_plan *plan, const sk_hand_surface *surface,
                          const double *dofs, const char *path);
/* The skinned hand as glTF binary: a pose (frame_count 1, no animation) or frames
 * (frame_count x SK_HAND_DOF_COUNT) as an animation; `surface` and, with lod_count 3, its
 * levels 1 and 2 of detail; the baked texture, the material. */
int hand_write_glb(const hand_surface_plan *plan, const sk_hand_surface *surface,
                   const double *dofs, int frame_count, double fps, bool animation, int lod_count,
                   const char *path);

/* `hand animate`'s surface outputs: --glb, --landmarks, --meshes-dir (--mesh-frames,
 * --skinning, --texture), each path NULL when not asked for (staged paths once reserved). */
typedef struct hand_animate_surface {
    const char *glb, *landmarks, *meshes_dir;
    bool *use; /* frame_count flags: the frames --mesh-frames lists (all without it) */
    hand_surface_plan plan;
} hand_animate_surface;
/* Parses and checks them against `frame_count` frames (before any work); free with
 * hand_animate_surface_free. */
int hand_animate_surface_parse(const cli_command *cmd, const cli_args *args,
                               const hand_params *params, int frame_count, hand_animate_surface *s);
void hand_animate_surface_free(hand_animate_surface *s);
int hand_animate_surface_write(const hand_animate_surface *s, const sk_hand_skeleton *skel,
                               const double *dofs, int frame_count, double fps);

#endif
