/* A sparse coverage mask in lazily allocated 64 x 64 tiles. The pieces of one stroke
 * (segments, joins) are rasterized into it taking the largest coverage per pixel, then
 * composited once, so overlapping pieces never blend twice. */
#include <stdlib.h>

#include "draw/draw_internal.h"

#define SK__MASK_TILE 64

bool sk__mask_init(sk__mask *mask, sk__clip bounds)
{
    mask->bounds = bounds;
    mask->failed = false;
    mask->tiles_x = (bounds.x1 - bounds.x0 + SK__MASK_TILE - 1) / SK__MASK_TILE;
    mask->tiles_y = (bounds.y1 - bounds.y0 + SK__MASK_TILE - 1) / SK__MASK_TILE;
    if (mask->tiles_x <= 0 || mask->tiles_y <= 0) {
        mask->tiles_x = mask->tiles_y = 0;
        mask->tiles = NULL;
        return true;
    }
    mask->tiles = calloc((size_t)mask->tiles_x * (size_t)mask->tiles_y, sizeof *mask->tiles);
    return mask->tiles != NULL;
}

void sk__mask_span_fn(void *user, int x, int y, int n, const float *coverage)
{
    sk__mask *mask = user;
    int ly = y - mask->bounds.y0;
    int lx = x - mask->bounds.x0;
    int ty = ly / SK__MASK_TILE;
    float **tile_row = mask->tiles + (size_t)ty * (size_t)mask->tiles_x;
    int i = 0;
    while (i < n) {
        int tx = (lx + i) / SK__MASK_TILE;
        int in_tile = lx + i - tx * SK__MASK_TILE;
        int run = SK__MASK_TILE - in_tile;
        if (run > n - i) run = n - i;
        float *tile = tile_row[tx];
        if (!tile) {
            bool any = false;
            for (int k = 0; k < run && !any; k++) any = coverage[i + k] > 0.0f;
            if (!any) {
                i += run;
                continue;
            }
            tile = calloc((size_t)SK__MASK_TILE * SK__MASK_TILE, sizeof *tile);
            if (!tile) {
                mask->failed = true;
                return;
            }
            tile_row[tx] = tile;
        }
        float *dst = tile + (size_t)(ly - ty * SK__MASK_TILE) * SK__MASK_TILE + in_tile;
        for (int k = 0; k < run; k++)
            if (coverage[i + k] > dst[k]) dst[k] = coverage[i + k];
        i += run;
    }
}

void sk__mask_paint(const sk__mask *mask, const sk__paint *paint)
{
    for (int ty = 0; ty < mask->tiles_y; ty++) {
        for (int tx = 0; tx < mask->tiles_x; tx++) {
            const float *tile = mask->tiles[(size_t)ty * (size_t)mask->tiles_x + (size_t)tx];
            if (!tile) continue;
            int x0 = mask->bounds.x0 + tx * SK__MASK_TILE;
            int y0 = mask->bounds.y0 + ty * SK__MASK_TILE;
            int w = mask->bounds.x1 - x0 < SK__MASK_TILE ? mask->bounds.x1 - x0 : SK__MASK_TILE;
            int h = mask->bounds.y1 - y0 < SK__MASK_TILE ? mask->bounds.y1 - y0 : SK__MASK_TILE;
            for (int r = 0; r < h; r++) sk__paint_span(paint, x0, y0 + r, w, tile + (size_t)r * SK__MASK_TILE);
        }
    }
}

void sk__mask_free(sk__mask *mask)
{
    if (mask->tiles) {
        size_t count = (size_t)mask->tiles_x * (size_t)mask->tiles_y;
        for (size_t i = 0; i < count; i++) free(mask->tiles[i]);
        free(mask->tiles);
    }
    mask->tiles = NULL;
}
