/* Private pieces shared by the maps module: the store of a skin map set (what it keeps
 * of every pixel between its render and its files) and which part of it each map reads. */
#ifndef SK_MAPS_INTERNAL_H
#define SK_MAPS_INTERNAL_H

#include <stddef.h>
#include <stdint.h>

#include "shitsukan/maps.h"

/* The parts of the store. */
enum {
    SK__STORE_HEIGHT = 1u << 0,  /* float mm: height.exr, height.png */
    SK__STORE_NORMAL = 1u << 1,  /* int16 x, y: normal.png, the preview at one sample */
    SK__STORE_FURROW = 1u << 2,  /* uint16 codes: furrow.png */
    SK__STORE_IDS = 1u << 3,     /* uint32 cell ids: cells.png */
    SK__STORE_PREVIEW = 1u << 4, /* float RGB: the preview with samples > 1 */
    SK__STORE_EDGES = 1u << 5    /* float RGB: edges.png */
};

struct sk_skin_maps {
    const sk_skin *skin;
    sk_skin_maps_desc desc; /* resolved */
    size_t n;               /* pixels of the region */
    unsigned parts;         /* the parts the set holds (allocated, not yet released) */
    unsigned rendered;      /* the parts rendered since they were allocated */
    sk_image height;
    int16_t *normal; /* 2 per pixel */
    uint16_t *furrow;
    uint32_t *ids;
    sk_image preview, edges; /* only when held */
    float furrow_span;       /* sk_skin_maps_furrow_span of the furrow level */
};

/* The parts of the store map `map` of a set with `samples` preview samples reads. */
unsigned sk__skin_map_parts(sk_skin_map map, int samples);

#endif
