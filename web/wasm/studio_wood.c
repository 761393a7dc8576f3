/* The wood panel's calls: a tree from preset JSON, the preset's view cut into buffers
 * (with the maps of `shitsukan wood cut --maps`, sk_wood_map), and the faces of a board
 * around that cut (the material on a board), all by sk_wood_cut. */
#include <math.h>
#include <string.h>

#include "shitsukan/maps.h"
#include "shitsukan/wood.h"
#include "studio.h"

STUDIO_API sk_wood *studio_wood_create(const char *json, sk_error *err)
{
    sk_wood_desc d;
    memset(&d, 0, sizeof d);
    if (studio_bind_json(json, &sk_wood_schema, &d, err) != SK_OK) return NULL;
    sk_wood *wood = NULL;
    if (sk_wood_create(&d, &wood, err) != SK_OK) return NULL;
    return wood;
}

STUDIO_API void studio_wood_destroy(sk_wood *wood) { sk_wood_destroy(wood); }

/* Rows [y0, y0 + rows) of the preset's view cut at width x height; outputs may be NULL. */
STUDIO_API int studio_wood_view(const sk_wood *wood, int width, int height, int y0, int rows,
                                int samples, float *shaded, float *albedo, float *fibre,
                                float *vessel, sk_error *err)
{
    sk_wood_cut_desc cut;
    memset(&cut, 0, sizeof cut);
    sk_wood_view_cut(wood, &sk_wood_get_desc(wood)->view, &cut);
    cut.width = width;
    cut.height = height;
    cut.region[0] = 0, cut.region[1] = y0, cut.region[2] = width, cut.region[3] = rows;
    cut.samples = samples;
    cut.shaded = shaded, cut.albedo = albedo, cut.fibre = fibre, cut.vessel = vessel;
    return (int)sk_wood_cut(wood, &cut, err);
}

/* The preset's view cut at width x height with the maps of `wood cut --maps`: maps[k]
 * NULL or the buffer of sk_wood_map k (width x height x its channels floats, the cut
 * output sk_wood_maps_cut_output names), `shaded` NULL or the shaded picture. */
STUDIO_API int studio_wood_view_maps(const sk_wood *wood, int width, int height, int samples,
                                     float *shaded, float **maps, sk_error *err)
{
    sk_wood_cut_desc cut;
    memset(&cut, 0, sizeof cut);
    sk_wood_view_cut(wood, &sk_wood_get_desc(wood)->view, &cut);
    cut.width = width;
    cut.height = height;
    cut.samples = samples;
    cut.shaded = shaded;
    for (int k = 0; k < SK_WOOD_MAP_COUNT; k++)
        *sk_wood_maps_cut_output(&cut, (sk_wood_map)k) = maps[k];
    return (int)sk_wood_cut(wood, &cut, err);
}

static sk_vec3f v_add(sk_vec3f a, sk_vec3f b, float s) { return sk_v3f_add(a, sk_v3f_scale(b, s)); }

/* Face `face` (0 top = the view's cut, 1 bottom, 2 near edge, 3 far edge, 4 left end,
 * 5 right end) of a board whose top is the view's cut (its width and aspect `aspect` =
 * breadth / width) and whose thickness is `thickness_mm`, rendered at width x height
 * pixels (shaded linear RGB). corners gets the face's top-left, top-right, bottom-left
 * corners in scene mm (9 floats), so the page can place the picture. */
STUDIO_API int studio_wood_board_face(const sk_wood *wood, int face, double aspect,
                                      double thickness_mm, int width, int height, int samples,
                                      float *shaded, float *corners, sk_error *err)
{
    sk_wood_cut_desc top;
    memset(&top, 0, sizeof top);
    sk_wood_view_cut(wood, &sk_wood_get_desc(wood)->view, &top);
    sk_vec3f n = sk_v3f_normalize(top.normal);
    sk_vec3f a = sk_v3f_normalize(v_add(top.axis, n, -sk_v3f_dot(top.axis, n)));
    sk_vec3f u = sk_v3f_cross(n, a);
    float w = top.width_mm, b = (float)(top.width_mm * aspect), t = (float)thickness_mm;
    /* centre of the board, then each face's centre, normal, x axis and size */
    sk_vec3f c = v_add(top.point, n, -0.5f * t);
    sk_vec3f fn, fa;
    float fw, fh, off;
    switch (face) {
    case 0:
        fn = n, fa = a, fw = w, fh = b, off = 0.5f * t;
        break;
    case 1:
        fn = sk_v3f_neg(n), fa = a, fw = w, fh = b, off = 0.5f * t;
        break;
    case 2:
        fn = sk_v3f_neg(u), fa = a, fw = w, fh = t, off = 0.5f * b;
        break;
    case 3:
        fn = u, fa = sk_v3f_neg(a), fw = w, fh = t, off = 0.5f * b;
        break;
    case 4:
        fn = sk_v3f_neg(a), fa = sk_v3f_neg(u), fw = b, fh = t, off = 0.5f * w;
        break;
    case 5:
        fn = a, fa = u, fw = b, fh = t, off = 0.5f * w;
        break;
    default:
        return (int)sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "face = %d is out of range [0, 5]",
                            face);
    }
    sk_vec3f fu = sk_v3f_cross(fn, fa);
    sk_wood_cut_desc cut = top;
    cut.point = v_add(c, fn, off);
    cut.normal = fn;
    cut.axis = fa;
    cut.width_mm = fw;
    cut.width = width;
    cut.height = height;
    memset(cut.region, 0, sizeof cut.region);
    cut.samples = samples;
    cut.shaded = shaded;
    cut.albedo = cut.fibre = cut.vessel = cut.dive = NULL;
    /* the picture's own height in mm is fw * height / width: the page asks for pixels in
       the face's proportions (fh / fw) */
    (void)fh;
    sk_vec3f tl = v_add(v_add(cut.point, fa, -0.5f * fw), fu, 0.5f * fw * height / width);
    sk_vec3f tr = v_add(tl, fa, fw);
    sk_vec3f bl = v_add(tl, fu, -fw * height / width);
    const sk_vec3f pts[3] = {tl, tr, bl};
    for (int i = 0; i < 3; i++)
        corners[3 * i] = pts[i].x, corners[3 * i + 1] = pts[i].y, corners[3 * i + 2] = pts[i].z;
    return (int)sk_wood_cut(wood, &cut, err);
}
