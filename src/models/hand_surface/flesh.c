/* Flesh sizes of the hand surface (thesis 4.1 builds its surface from a scanned cast;
 * here the surface is built from the skeleton with published anthropometry): the
 * built-in values of presets/hand/flesh.json and a strict reader of that format. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "models/hand_surface/surface_internal.h"
#include "shitsukan/io.h"

void sk_hand_flesh_default(sk_hand_flesh *f)
{
    memset(f, 0, sizeof *f);
    f->reference_breadth_mm = 85;
    static const double breadth[5][4] = {{22, 21, 17.5, 0},
                                         {19, 20, 17.5, 15.5},
                                         {19, 20.5, 18, 16},
                                         {17, 19, 16.5, 15},
                                         {15.5, 16.5, 15, 13.5}};
    static const double thickness[5][4] = {{20, 18, 13.5, 0},
                                           {20, 18, 15, 12.5},
                                           {20.5, 18.5, 15, 13},
                                           {19, 17, 14, 12},
                                           {17, 15, 12.5, 11}};
    static const double mc_breadth[5][2] = {{18, 21}, {22, 30}, {20, 22}, {18, 20}, {20, 27}};
    static const double mc_thickness[5][2] = {{18, 19}, {28, 26}, {30, 27}, {28, 25}, {24, 22}};
    for (int i = 0; i < SK_HAND_FINGER_COUNT; i++) {
        memcpy(f->finger[i].breadth_mm, breadth[i], sizeof breadth[i]);
        memcpy(f->finger[i].thickness_mm, thickness[i], sizeof thickness[i]);
        memcpy(f->finger[i].metacarpal_breadth_mm, mc_breadth[i], sizeof mc_breadth[i]);
        memcpy(f->finger[i].metacarpal_thickness_mm, mc_thickness[i], sizeof mc_thickness[i]);
    }
    f->palm_palmar_shift_mm = 3;
    f->wrist_breadth_mm = 60;
    f->wrist_thickness_mm = 38;
    f->stump_length_mm = 30;
    f->thenar = (sk_hand_flesh_pad){0.17, 0.2, 8, {15, 22, 11}, -30};
    f->hypothenar = (sk_hand_flesh_pad){-0.33, 0.24, 5, {12, 26, 10}, 5};
    f->web_reach = 0.38;
    f->web_thickness_mm = 9;
    f->thumb_web_thickness_mm = 11;
    f->nail_length = 0.55;
    f->nail_breadth = 0.75;
    f->nail_thickness_mm = 0.5;
    f->blend_joint_mm = 3;
    f->blend_root_mm = 5;
    f->blend_palm_mm = 8;
}
