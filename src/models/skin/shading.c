/* Shaded preview (paper sec. 5: bump mapping after Blinn 1978; the shape is not built,
 * only normals): Lambert under a directional light plus uniform sky light, and a soft
 * Blinn-Phong highlight, on a skin-tone albedo, viewed from straight above. */
#include <math.h>

#include "models/skin/skin_internal.h"

sk_vec3f sk_skin_shade(const sk_skin *skin, sk_vec3f n)
{
    float nl = n.x * skin->light[0] + n.y * skin->light[1] + n.z * skin->light[2];
    float diffuse = skin->sky + skin->sun * (nl > 0.0f ? nl : 0.0f);
    float spec = 0.0f;
    if (nl > 0.0f && skin->spec > 0.0f) {
        float nh = n.x * skin->half[0] + n.y * skin->half[1] + n.z * skin->half[2];
        if (nh > 0.0f) {
            float pw;
            if (skin->shininess_int > 0) {
                /* integer exponent: repeated squaring */
                pw = 1.0f;
                float b = nh;
                for (int e = skin->shininess_int; e; e >>= 1, b *= b)
                    if (e & 1) pw *= b;
            } else {
                pw = powf(nh, skin->shininess);
            }
            spec = skin->spec * skin->sun * pw;
        }
    }
    sk_vec3f c;
    c.x = sk_clampf(skin->albedo[0] * diffuse + spec, 0.0f, 1.0f);
    c.y = sk_clampf(skin->albedo[1] * diffuse + spec, 0.0f, 1.0f);
    c.z = sk_clampf(skin->albedo[2] * diffuse + spec, 0.0f, 1.0f);
    return c;
}
