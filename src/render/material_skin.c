/* The skin material: the microrelief of Ishii et al. 1991 as a bump map (Blinn 1978), as
 * in the paper's Fig. 20. The height field is evaluated exactly at every shading point
 * (st in mm), not read from a texture, so the relief stays sharp at any distance. */
#include <math.h>

#include "render/render_internal.h"

sk_result sk__skin_material_build(sk__material *m, int index, sk_error *err)
{
    sk_result r = sk_skin_create(&m->skin, &m->desc.skin, err);
    return r == SK_OK ? r : sk_error_prefix(err, r, "materials[%d].skin", index);
}

void sk__skin_material_destroy(sk__material *m)
{
    if (m->skin) sk_skin_destroy(m->skin);
    m->skin = NULL;
}

void sk__skin_material_texel(const sk__material *m, const sk_render_surface *s, sk_render_texel *tx)
{
    sk_vec3f n;
    sk_skin_eval(m->skin, s->st.x, s->st.y, NULL, &n);
    /* the normal of the height field is normalize(-dh/dx, -dh/dy, 1) */
    if (n.z > 1e-6f) {
        tx->slope.x -= n.x / n.z;
        tx->slope.y -= n.y / n.z;
    }
}
