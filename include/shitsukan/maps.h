/* shitsukan maps: the map sets a renderer takes, one home for every front end (the
 * command's `shitsukan skin maps` and `shitsukan wood cut --maps`, the studio's exports
 * and live maps): which files a set holds, how each map is kept between the render and
 * its file, how its samples become the file's integer codes, and how those decode (the
 * files' metadata). Writing the files is the caller's: the PNG and EXR writers of image.h
 * take the rows, a page writes the codes itself.
 *
 * Thread-safety: the tables are constant; a skin map set is rendered by one caller at a
 * time (its render is parallel inside), and read (rows, codes) from any number of threads
 * once rendered. */
#ifndef SHITSUKAN_MAPS_H
#define SHITSUKAN_MAPS_H

#include <stdbool.h>
#include <stdint.h>

#include "shitsukan/core.h"
#include "shitsukan/image.h"
#include "shitsukan/skin.h"
#include "shitsukan/wood.h"

#ifdef __cplusplus
extern "C" {
#endif

/* One file of a map set. */
typedef struct sk_map_info {
    const char *file;     /* its name in the set's folder, e.g. "normal.png" */
    const char *name;     /* the map's short name, unique in its set ("height", "height_mm") */
    int channels;         /* 1 (grey) or 3 (RGB) */
    int bit_depth;        /* 8 or 16 (PNG codes); 32: float samples (EXR) */
    bool srgb;            /* codes by the sRGB curve (else linear: code = round(v x max)) */
    const char *encoding; /* what the samples mean, for the file's "shitsukan:encoding";
                             NULL when the set's decode rule depends on the skin (skin
                             maps: sk_skin_maps_metadata) or none is written */
} sk_map_info;

/* ------------------------------------------------------------------ skin maps */
/* The maps of `shitsukan skin maps` (Ishii et al. 1991's relief), in the order the
 * command writes them. The samples in [0, 1] each PNG codes: */
typedef enum sk_skin_map {
    SK_SKIN_MAP_HEIGHT_MM = 0, /* height.exr: the height in mm (float) */
    SK_SKIN_MAP_HEIGHT,        /* height.png: (h - min) / (max - min) over sk_skin_height_range */
    SK_SKIN_MAP_FURROW,        /* furrow.png: distance to the furrow level's furrows over the
                                  furrow span (sk_skin_maps_furrow_span), clamped at 1 */
    SK_SKIN_MAP_CELLS,         /* cells.png: sk_skin_cell_color of the id level's cell */
    SK_SKIN_MAP_NORMAL,        /* normal.png: 0.5 n + 0.5 of the tangent-space normal (OpenGL:
                                  green up; DirectX: green down) */
    SK_SKIN_MAP_PREVIEW,       /* preview.png: the shaded preview (sRGB codes) */
    SK_SKIN_MAP_EDGES,         /* edges.png: the preview with every level's furrows drawn */
    SK_SKIN_MAP_COUNT
} sk_skin_map;

/* Bit of a map in a set of maps (sk_skin_maps_desc.maps, sk_skin_maps_render). */
#define SK_SKIN_MAP_BIT(map) (1u << (map))
/* Every map but edges.png (the default set). */
#define SK_SKIN_MAPS_DEFAULT (SK_SKIN_MAP_BIT(SK_SKIN_MAP_EDGES) - 1u)

/* Rows of one band: a set renders its region in bands of this many rows, shared out
 * between the threads. */
#define SK_SKIN_MAPS_BAND_ROWS 4

/* The file of a map (NULL outside [0, SK_SKIN_MAP_COUNT)). */
const sk_map_info *sk_skin_map_info(sk_skin_map map);

/* What a set keeps of every pixel between its render and its files (the store): the
 * height in mm (float), the normal's x and y in 1/32767 (z follows), the furrow distance
 * as furrow.png's 16-bit code and the cell id, 14 bytes a pixel; with samples > 1 the
 * preview, and edges.png, as float RGB (12 bytes a pixel each). normal.png and the
 * preview at one sample come from the kept normal, within one code of the float normal's
 * in about 0.1 % of the samples. */
typedef struct sk_skin_maps_desc {
    int width, height;    /* pixels of the whole map (covering the tile), [1, 65536] */
    int region[4];        /* x, y, w, h of the part the set holds; all 0 = the whole map.
                             Pixels are identical to the whole map's. */
    unsigned maps;        /* SK_SKIN_MAP_BITs of the maps the set holds; 0 = the default
                             (every map but edges.png) */
    int furrow_level;     /* level furrow.png measures, [1, level_count]; 0 = 1 */
    int id_level;         /* level whose cells cells.png colours, [1, level_count]; 0 = 1 */
    int samples;          /* preview and edges samples per pixel side, [1, 8]; 0 = 1 */
    bool directx;         /* normal.png in the DirectX convention (green down) */
    sk_progress progress; /* of sk_skin_maps_render */
} sk_skin_maps_desc;

typedef struct sk_skin_maps sk_skin_maps;

/* The bytes a set of `desc` keeps per pixel of its region (for memory caps). */
double sk_skin_maps_bytes_per_pixel(const sk_skin_maps_desc *desc);
/* The span furrow.png's codes cover for a furrow level (0 = 1): half the level's
 * spacing, the whole ridge from its centre to its edge. 0 for a level the skin has not. */
float sk_skin_maps_furrow_span(const sk_skin *skin, int furrow_level);

/* A set for `skin` (referenced, not copied: it must outlive the set; a re-profiled skin,
 * sk_skin_reprofile, is read as it then is). Its store is allocated here; nothing is
 * rendered. Errors: sizes, region or levels out of range (SK_ERROR_INVALID_ARGUMENT), a
 * store that would exceed SK_IMAGE_MAX_BYTES (SK_ERROR_LIMIT), out of memory. */
sk_result sk_skin_maps_create(sk_skin_maps **out, const sk_skin *skin,
                              const sk_skin_maps_desc *desc, sk_error *err);
void sk_skin_maps_destroy(sk_skin_maps *maps);
/* The desc the set was made with, resolved (region, maps, levels and samples filled in). */
const sk_skin_maps_desc *sk_skin_maps_get_desc(const sk_skin_maps *maps);
bool sk_skin_maps_holds(const sk_skin_maps *maps, sk_skin_map map);

/* Renders into the store what the maps `which` (SK_SKIN_MAP_BITs; 0 = every map the set
 * holds) are made from: the region in bands of SK_SKIN_MAPS_BAND_ROWS rows in one
 * parallel loop, each band rendered by one thread (sk_skin_render) and stored at once;
 * maps of little work run on one thread. Only the relief maps (heights, normal, preview,
 * edges) evaluate the relief: furrow.png and cells.png alone are much cheaper. The same
 * bytes for any thread count. Progress goes to the desc's sink. */
sk_result sk_skin_maps_render(sk_skin_maps *maps, unsigned which, sk_error *err);

/* The samples of rows [y0, y0 + rows) of the region (row 0 its top) of a map as its file
 * codes them: region width x rows x channels floats (height.exr: mm; the others in
 * [0, 1]). The preview at one sample is shaded here from the kept normals with the skin's
 * shading as it now is. Fails for a map the set does not hold, has not rendered or has
 * released (SK_ERROR_INVALID_ARGUMENT). */
sk_result sk_skin_maps_rows(const sk_skin_maps *maps, sk_skin_map map, int y0, int rows,
                            float *samples, sk_error *err);
/* The same as the integer codes of the map's file (the PNG writer's rounding, sRGB or
 * linear by sk_map_info): 8-bit codes of any PNG map (of a 16-bit one: the 8-bit file it
 * would be), 16-bit codes of a 16-bit map. */
sk_result sk_skin_maps_codes8(const sk_skin_maps *maps, sk_skin_map map, int y0, int rows,
                              uint8_t *codes, sk_error *err);
sk_result sk_skin_maps_codes16(const sk_skin_maps *maps, sk_skin_map map, int y0, int rows,
                               uint16_t *codes, sk_error *err);
/* The map held as a float image (height.exr's heights; the preview with samples > 1;
 * edges.png), or NULL when it is made row by row from the store. */
const sk_image *sk_skin_maps_image(const sk_skin_maps *maps, sk_skin_map map);
/* Frees the parts of the store that no map after `map` (in sk_skin_map order) reads:
 * called after each file is written, in order, the set holds less and less. */
void sk_skin_maps_release(sk_skin_maps *maps, sk_skin_map map);

/* The keys of every skin image of a `width`-pixel-wide map (the preview of `shitsukan
 * skin` too): shitsukan:seed, shitsukan:tile_mm, shitsukan:mm_per_pixel,
 * shitsukan:seamless and, when not NULL, Software. */
sk_result sk_skin_image_metadata(const sk_skin *skin, int width, const char *software,
                                 sk_image_metadata *meta, sk_error *err);
/* The metadata of a map's file: the keys above, then the map's own: height.exr and
 * height.png shitsukan:units and the height range (shitsukan:height_min_mm, _max_mm),
 * height.png and furrow.png the decode rule of their codes (shitsukan:decode), furrow.png
 * shitsukan:furrow_level, normal.png shitsukan:normal_convention. */
sk_result sk_skin_maps_metadata(const sk_skin_maps *maps, sk_skin_map map, const char *software,
                                sk_image_metadata *meta, sk_error *err);

/* The store's encodings, pixel by pixel. A normal's x and y as kept: round(32767 v); back
 * to a unit normal with z = sqrt(1 - x^2 - y^2) (0 where that is negative). */
void sk_skin_maps_store_normal(const float normal[3], int16_t xy[2]);
void sk_skin_maps_load_normal(const int16_t xy[2], float normal[3]);
/* furrow.png's code of a distance: round(min(distance / span, 1) x 65535). */
uint16_t sk_skin_maps_furrow_code(float distance_mm, float span_mm);

/* ------------------------------------------------------------------ wood maps */
/* The maps of `shitsukan wood cut --maps` (Kawai 2000's solid texture on a cut), in the
 * order the command writes them; each is a cut output as it is (sk_wood_cut_desc). */
typedef enum sk_wood_map {
    SK_WOOD_MAP_ALBEDO = 0, /* albedo.png: linear albedo as 8-bit sRGB */
    SK_WOOD_MAP_FIBRE,      /* fibre.png: 16-bit linear 0.5 + 0.5 f, f the unit fibre
                               direction up the tree in the cut's frame */
    SK_WOOD_MAP_PORES,      /* pores.png: 8-bit linear vessel (pore) coverage */
    SK_WOOD_MAP_COUNT
} sk_wood_map;

/* The file of a map (NULL outside [0, SK_WOOD_MAP_COUNT)). */
const sk_map_info *sk_wood_map_info(sk_wood_map map);
/* The output field of `cut` a map is rendered into (&cut->albedo, &cut->fibre,
 * &cut->vessel): set it to a buffer of region pixels x the map's channels; NULL outside. */
float **sk_wood_maps_cut_output(sk_wood_cut_desc *cut, sk_wood_map map);
/* Adds a map's own metadata (its shitsukan:encoding, where it has one) to `meta`. */
sk_result sk_wood_maps_metadata(sk_wood_map map, sk_image_metadata *meta, sk_error *err);

#ifdef __cplusplus
}
#endif

#endif /* SHITSUKAN_MAPS_H */
