/* Preset schemas of the hand surface (Yasumuro 2000, sec. 4.1): the meshed skin's size
 * and grid, the baked texture (4.1.6), and the names of the skinning methods and glTF
 * materials. Each key's range and default are stated here once; the checks read them. */
#include <stddef.h>

#include "shitsukan/hand_surface.h"

const char *const sk_hand_skinning_names[] = {"default", "rigid", "lbs", "dqs", NULL};
const char *const sk_hand_gltf_material_names[] = {"default", "blend", "pbr", NULL};

static const sk_schema_field surface_fields[] = {
    SK_SCHEMA_INT(sk_hand_surface_desc, triangles, "triangles", 500, 200000, .flags = SK_FIELD_ZERO,
                  .def = 8000, .doc = "target triangle count of level 0 (8000: the thesis's)"),
    SK_SCHEMA_DOUBLE(sk_hand_surface_desc, cell_mm, "cell_mm", 0.2, 4, .flags = SK_FIELD_ZERO,
                     .def_text = "chosen from the hand size and the triangle count",
                     .doc = "grid step of the implicit surface's meshing (mm)"),
};
const sk_schema sk_hand_surface_schema =
    SK_SCHEMA_OF("surface", sk_hand_surface_desc, surface_fields);

static const sk_schema_field texture_fields[] = {
    SK_SCHEMA_INT(sk_hand_texture_desc, size, "size", 64, 8192, .flags = SK_FIELD_ZERO, .def = 1024,
                  .doc = "atlas width = height in pixels"),
    SK_SCHEMA_DOUBLE(sk_hand_texture_desc, relief_scale, "relief_scale", 0, 100, .def = 1,
                     .doc = "multiplies the skin microrelief's height"),
    SK_SCHEMA_DOUBLE(sk_hand_texture_desc, crease_depth_mm, "crease_depth_mm", 0, 5, .def = 0.25,
                     .doc = "depth of the joint and palm creases (mm)"),
    SK_SCHEMA_DOUBLE(sk_hand_texture_desc, seam_width, "seam_width", 1e-3, 1,
                     .flags = SK_FIELD_ZERO, .def = 0.3,
                     .doc = "palm and back blend where |normal.z| is below this"),
};
const sk_schema sk_hand_texture_schema =
    SK_SCHEMA_OF("texture", sk_hand_texture_desc, texture_fields);
