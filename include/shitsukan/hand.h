/* shitsukan hand: the skeleton and natural posture of Yasumuro's thesis (2000, ch. 3),
 * its skin surface and the scan pipeline (ch. 4), in four headers by module:
 *   hand_posture.h   skeleton, posture solver, potentials and prior, animation, export
 *   hand_pictures.h  stick figures, frame sequences and angle plots
 *   hand_surface.h   the skin surface, skinning, levels of detail, exports, texture
 *   hand_scan.h      the scan-to-surface pipeline
 * This header includes all four (docs/architecture.md). */
#ifndef SHITSUKAN_HAND_H
#define SHITSUKAN_HAND_H

#include "shitsukan/hand_posture.h"
#include "shitsukan/hand_pictures.h"
#include "shitsukan/hand_surface.h"
#include "shitsukan/hand_scan.h"

#endif /* SHITSUKAN_HAND_H */
