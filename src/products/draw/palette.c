/* The default qualitative palette: the colour-blind-safe set of Okabe & Ito (2008,
 * "Color Universal Design"), sRGB values decoded to linear RGB, ordered for lines on
 * white (the low-contrast yellow last). */
#include "products/draw/draw_internal.h"

sk_color sk_palette(int index)
{
    static const sk_color colors[SK_PALETTE_SIZE] = {
        {0.000000f, 0.168269f, 0.445201f, 1.0f}, /* blue            #0072B2 */
        {0.665387f, 0.111932f, 0.000000f, 1.0f}, /* vermillion      #D55E00 */
        {0.000000f, 0.341914f, 0.171441f, 1.0f}, /* bluish green    #009E73 */
        {0.603827f, 0.191202f, 0.386429f, 1.0f}, /* reddish purple  #CC79A7 */
        {0.791298f, 0.346704f, 0.000000f, 1.0f}, /* orange          #E69F00 */
        {0.093059f, 0.456411f, 0.814847f, 1.0f}, /* sky blue        #56B4E9 */
        {0.000000f, 0.000000f, 0.000000f, 1.0f}, /* black           #000000 */
        {0.871367f, 0.775822f, 0.054480f, 1.0f}, /* yellow          #F0E442 */
    };
    int i = index % SK_PALETTE_SIZE;
    if (i < 0) i += SK_PALETTE_SIZE;
    return colors[i];
}
