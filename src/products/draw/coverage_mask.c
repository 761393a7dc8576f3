/* A sparse coverage mask in lazily allocated 32 x 32 tiles. The pieces of one stroke
 * (segments, joins) are rasterized into it taking the largest coverage per pixel, then
 * composited once, so overlapping pieces never blend twice. */
#include <stdlib.h>

#include "products/draw/draw_internal.h"

#define SK__MASK_TILE 32

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
    int row = ly - ty * SK__MASK_TILE;
    sk__mask_tile *tile_row = mask->tiles + (size_t)ty * (size_t)mask->tiles_x;
    int i = 0;
    while (i < n) {
        int tx = (lx + i) / SK__MASK_TILE;
        int col = lx + i - tx * SK__MASK_TILE;
        int run = SK__MASK_TILE - col;
        if (run > n - i) run = n - i;
        sk__mask_tile *tile = &tile_row[tx];
        if (!tile->coverage) {
            tile->coverage = calloc((size_t)SK__MASK_TILE * SK__MASK_TILE, sizeof(float));
            if (!tile->coverage) {
                mask->failed = true;
                return;
            }
            tile->x0 = tile->y0 = SK__MASK_TILE;
            tile->x1 = tile->y1 = 0;
        }
        float *dst = tile->coverage + (size_t)row * SK__MASK_TILE + col;
        for (int k = 0; k < run; k++)
            if (coverage[i + k] > dst[k]) dst[k] = coverage[i + k];
        if (col < tile->x0) tile->x0 = (short)col;
        if (col + run > tile->x1) tile->x1 = (short)(col + run);
        if (row < tile->y0) tile->y0 = (short)row;
        if (row + 1 > tile->y1) tile->y1 = (short)(row + 1);
        i += run;
    }
}

void sk__mask_paint(const sk__mask *mask, const sk__paint *paint)
{
    for (int ty = 0; ty < mask->tiles_y; ty++) {
        for (int tx = 0; tx < mask->tiles_x; tx++) {
            const sk__mask_tile *tile =
                &mask->tiles[(size_t)ty * (size_t)mask->tiles_x + (size_t)tx];
            if (!tile->coverage) continue;
            int x0 = mask->bounds.x0 + tx * SK__MASK_TILE + tile->x0;
            int y0 = mask->bounds.y0 + ty * SK__MASK_TILE;
            for (int r = tile->y0; r < tile->y1; r++)
                sk__paint_span(paint, x0, y0 + r, tile->x1 - tile->x0,
                               tile->coverage + (size_t)r * SK__MASK_TILE + tile->x0);
        }
    }
}

void sk__mask_free(sk__mask *mask)
{
    if (mask->tiles) {
        size_t count = (size_t)mask->tiles_x * (size_t)mask->tiles_y;
        for (size_t i = 0; i < count; i++) free(mask->tiles[i].coverage);
        free(mask->tiles);
    }
    mask->tiles = NULL;
}
