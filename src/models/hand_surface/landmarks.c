/* The 21 hand landmarks of the common hand-pose datasets' order (wrist; then per finger
 * from thumb to little, base to tip: thumb CMC, MCP, IP, tip; index..little MCP, PIP,
 * DIP, tip) from the skeleton's joint centres, per frame, as CSV or JSON. The tips are
 * the ends of the distal links, where the surface's fingertips are. */
#include <stdio.h>
#include <stdlib.h>

#include "models/hand_surface/surface_internal.h"
#include "shitsukan/io.h"

static const char *const names[SK_HAND_LANDMARK_COUNT] = {
    "wrist",     "thumb_cmc", "thumb_mcp",  "thumb_ip",   "thumb_tip",  "index_mcp",  "index_pip",
    "index_dip", "index_tip", "middle_mcp", "middle_pip", "middle_dip", "middle_tip", "ring_mcp",
    "ring_pip",  "ring_dip",  "ring_tip",   "little_mcp", "little_pip", "little_dip", "little_tip"};

const char *sk_hand_landmark_name(int i)
{
    return i >= 0 && i < SK_HAND_LANDMARK_COUNT ? names[i] : NULL;
}

int sk_hand_landmark_point(int i)
{
    if (i < 0 || i >= SK_HAND_LANDMARK_COUNT) return -1;
    if (i == 0) return 0;
    if (i <= 4) return i; /* T.CMC T.MCP T.IP T.tip are points 1..4 */
    int finger = (i - 5) / 4, k = (i - 5) % 4;
    return 5 + 5 * finger + 1 + k; /* skip each finger's CMC */
}
