/* Helpers shared by the hand surface commands (`hand mesh`, and the surface outputs of
 * `hand animate`): argument parsing and the calls into the library. */
#ifndef SK_TOOLS_CMD_HAND_SURFACE_H
#define SK_TOOLS_CMD_HAND_SURFACE_H

#include "cli.h"
#include "shitsukan/hand.h"

/* "rigid", "lbs", "dqs" (NULL = dqs); prints the error and returns 2 on another. */
int hand_parse_skinning(const char *text, sk_hand_skinning *out);
/* The surface of the skeleton from --triangles and --flesh, at level of detail `lod`. */
int hand_build_surface(const cli_command *cmd, const cli_args *args, const sk_hand_skeleton *skel, int lod,
                       sk_hand_surface **out);
/* One pose as OBJ or PLY (by extension), with --texture's maps. */
int hand_write_posed_mesh(const cli_command *cmd, const cli_args *args, const sk_hand_surface *surface,
                          const double *dofs, sk_hand_skinning method, const char *path);
/* The skinned hand as glTF binary: a pose (frame_count 1, no animation) or frames
 * (frame_count x SK_HAND_DOF_COUNT) as an animation; `surface` and, with lod_count 3, its
 * levels 1 and 2 of detail; the baked texture (--texture-size), the material (--material). */
int hand_write_glb(const cli_command *cmd, const cli_args *args, const sk_hand_surface *surface, const double *dofs,
                   int frame_count, double fps, bool animation, int lod_count, sk_hand_skinning method,
                   const char *path);

/* `hand animate`'s surface outputs: --glb, --landmarks, --meshes-dir (--mesh-frames,
 * --skinning, --texture). */
int hand_animate_surface_outputs(const cli_command *cmd, const cli_args *args, const sk_hand_skeleton *skel,
                                 const double *dofs, int frame_count, double fps);

#endif
