/* The unified end-grain attribute array C'(t, theta) (Kawai 2000 sec. 6.3). The ring part
 * is a profile across each ring: earlywood, then (over `transition`) a linear rise into
 * the latewood band of `latewood_fraction`, then the abrupt return to earlywood at the
 * next ring boundary; it can be box-filtered exactly through its antiderivative. The
 * brightness-shift part (sec. 6.2, Momoi's method through the grain transform) adds to
 * every cell of the (t, theta) array an independent shift, uniform over a range of
 * `brightness_shift` (Fig. 7: 40 %) centred on the ring's brightness, from a hash of the
 * cell, so the array is unbounded and costs no memory. Brightness is taken as the sRGB
 * encoded value, the lightness an image shows (the paper adds the shift to the array's
 * reflectance without naming a scale; in linear terms the same shift would swallow dark
 * latewood). The paper's "at most 40 %" leaves the sign open: the range is centred so
 * that the rings keep their mean colour. The shift can also multiply the colour by
 * (1 - shift u) instead, which only darkens. An optional fibre length redraws the shift
 * along the fibre (beyond the paper, whose projection is endless). */
#include "models/wood/attributes.h"

#include <math.h>

#include "shitsukan/image.h"
#include "models/wood/numeric.h"

sk_vec3f sk__linear_from_srgb3(const float c[3])
{
    return sk_v3f(sk_linear_from_srgb(c[0]), sk_linear_from_srgb(c[1]), sk_linear_from_srgb(c[2]));
}

void sk__attributes_init(sk__attributes *attr, const sk_wood_desc *desc)
{
    attr->earlywood = sk__linear_from_srgb3(desc->rings.earlywood_srgb);
    attr->latewood = sk__linear_from_srgb3(desc->rings.latewood_srgb);
    attr->vessel = sk__linear_from_srgb3(desc->vessels.color_srgb);
    double lw = desc->rings.latewood_fraction, tr = desc->rings.transition;
    if (tr > 1.0 - lw) tr = 1.0 - lw;
    attr->late_start = 1.0 - lw;
    attr->early_end = attr->late_start - tr;
    attr->per_year = 0.5 * tr + lw;
    attr->shift = desc->fibre.brightness_shift;
    attr->shift_add = desc->fibre.shift_mode != SK_WOOD_SHIFT_MULTIPLY;
    if (attr->shift > 0.0 && attr->shift_add)
        for (int k = 0; k <= SK__SHIFT_TABLE; k++) {
            float x = (float)k / (float)SK__SHIFT_TABLE;
            attr->to_srgb[k] = sk_srgb_from_linear(x);
            attr->from_srgb[k] = sk_linear_from_srgb(x);
        }
    attr->rows_per_year = desc->rings.width_mm / desc->fibre.cell_mm;
    attr->length = desc->fibre.length_mm;
    attr->inv_length = attr->length > 0.0 ? 1.0 / attr->length : 0.0;
    attr->seed = sk_hash(desc->seed, 0x73686674ULL /* "shft" */, 0, 0);
}
