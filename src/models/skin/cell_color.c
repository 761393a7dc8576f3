/* A colour per cell id, stable for a seed's cells: the cells map of the map set, for
 * per-ridge variation in shaders. */
#include "shitsukan/skin.h"

void sk_skin_cell_color(uint32_t id, float rgb[3])
{
    uint64_t h = sk_hash(0x43454c4cULL, id, 0, 0);
    for (int i = 0; i < 3; i++) rgb[i] = (float)((h >> (16 * i)) & 0xffff) / 65535.0f;
}
