/* shitsukan noise maps: tileable fractal (fBm) gradient-noise textures rendered from the
 * core noise, in [0, 1], for use as masks, roughness variation or test inputs.
 *
 * Thread-safety: sk_noise_map_render is thread-safe; it runs in parallel internally and
 * gives the same pixels for any thread count and any region. */
#ifndef SHITSUKAN_NOISE_MAP_H
#define SHITSUKAN_NOISE_MAP_H

#include "shitsukan/core.h"
#include "shitsukan/image.h"
#include "shitsukan/preset.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct sk_noise_map_desc {
    uint64_t seed; /* default 0 */
    int width;     /* full map width in pixels; 0 = 512; range 1..65536 */
    int height;    /* full map height in pixels; 0 = width; range 1..65536 */
    float cells;   /* noise lattice cells across the width (base frequency); 0 = 8; [1e-3, 4096] */
    sk_fbm_desc fbm; /* octaves, lacunarity, gain; zero fields = 5, 2, 0.5 */
    bool seamless;   /* wrap the lattice so the map tiles; default false (presets turn it on) */
    sk_progress progress;
} sk_noise_map_desc;

/* Fills zero fields with the defaults above. */
sk_noise_map_desc sk_noise_map_desc_resolved(const sk_noise_map_desc *desc);
/* Checks a resolved desc; errors name the field and range. */
sk_result sk_noise_map_desc_validate(const sk_noise_map_desc *desc, sk_error *err);

/* Renders the sub-rectangle region = {x, y, w, h} of the full map (NULL = all of it) into
 * `out`, which must be a 1-channel image of w x h. Values are 0.5 + 0.5 * fBm, in [0, 1].
 * With `seamless` the lattice period is rounded to whole cells in x and y (so non-square
 * maps still tile). */
sk_result sk_noise_map_render(const sk_noise_map_desc *desc, const int region[4], sk_image *out,
                              sk_error *err);

/* Preset schema: seed, width, height, cells, octaves, lacunarity, gain, seamless. */
extern const sk_schema sk_noise_map_schema;

#ifdef __cplusplus
}
#endif

#endif /* SHITSUKAN_NOISE_MAP_H */
