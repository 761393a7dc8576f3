/* shitsukan hand pictures: stick figures of posed skeletons, frame sequences and
 * joint-angle plots (the hand-products module). The functions keep no state and are
 * thread-safe. */
#ifndef SHITSUKAN_HAND_PICTURES_H
#define SHITSUKAN_HAND_PICTURES_H

#include "shitsukan/draw.h"
#include "shitsukan/hand_posture.h"
#include "shitsukan/image.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---------------------------------------------------------------- pictures */
/* Stick figures of posed skeletons: bones as anti-aliased lines, joints as discs, one
 * colour per finger, the palm as a translucent plate, the end of the (fixed) forearm
 * below the wrist, direction arrows and a scale bar. Orthographic views along the world
 * axes; with the wrist rotations at zero they are the anatomical views named below. */
typedef enum sk_hand_view {
    SK_HAND_VIEW_DEFAULT = 0, /* in a view list: dorsal for the first view, radial for
                                 the second, palmar, ulnar */
    SK_HAND_VIEW_DORSAL,      /* from the back of the hand (camera on world -Z), fingers
                                 up: a right hand's thumb is on the left */
    SK_HAND_VIEW_PALMAR,      /* from the palm side (camera on +Z), fingers up */
    SK_HAND_VIEW_RADIAL,      /* from the thumb side (camera on +X for a right hand, -X
                                 for a left one), fingers up: a right hand's palm faces
                                 left, so flexion curls the fingers to the left */
    SK_HAND_VIEW_ULNAR        /* from the little-finger side, fingers up */
} sk_hand_view;

#define SK_HAND_DRAW_MAX_VIEWS 4

typedef enum sk_hand_framing {
    SK_HAND_FRAMING_DEFAULT = 0, /* = REACH */
    SK_HAND_FRAMING_REACH,       /* the window holds every pose of the skeleton's reach
                                    (flat, relaxed, fist, full extension, spread) as well
                                    as the given poses: one scale and placement for all
                                    poses of a hand, so animation frames and separate
                                    pictures line up */
    SK_HAND_FRAMING_TIGHT        /* the window fits the given poses only */
} sk_hand_framing;

typedef struct sk_hand_draw_desc {
    int width, height;                          /* whole picture in pixels; 0 = 400 per view x 480;
                                                   range 0 or 64..8192 */
    int view_count;                             /* side-by-side panels; 0 = 2; range 0..4 */
    sk_hand_view views[SK_HAND_DRAW_MAX_VIEWS]; /* DEFAULT entries: see sk_hand_view */
    sk_hand_framing framing;                    /* 0 = REACH */
    int text_scale;         /* bitmap-font scale of titles and labels; 0 = 2 if the
                               picture is at least 400 pixels high, else 1; range 0..8 */
    const char *caption;    /* NULL or "" = none; a line under the panels (e.g. the
                               driven DOFs and their values), wrapped onto two lines at
                               ", " when too wide, shrunk or cut if still too wide */
    bool label_points;      /* write every joint's name beside it ("I.MCP", ...) */
    bool hide_panel_titles; /* false = each panel's view name above it */
    bool hide_cues;         /* false = forearm end, direction arrows and scale bar */
} sk_hand_draw_desc;

/* Where a panel shows the world: a world point p lands at pixel
 *   (origin_x + s * dot(p, right), origin_y - s * dot(p, up)), s = pixels_per_mm,
 * and dot(p, toward) is its nearness to the viewer: drawing goes far to near, and parts
 * farther than the wrist fade toward the background (a depth cue). */
typedef struct sk_hand_panel {
    sk_hand_view view;
    int x0, y0, width, height;  /* the panel's rectangle in the picture */
    sk_vec3d right, up, toward; /* world unit vectors of screen right, screen up and
                                   toward the viewer (right = up x toward) */
    double origin_x, origin_y;  /* pixel position of the world origin */
} sk_hand_panel;

typedef struct sk_hand_draw_layout {
    int width, height, text_scale;
    int view_count;
    sk_hand_panel panel[SK_HAND_DRAW_MAX_VIEWS];
    double pixels_per_mm; /* the same in every panel */
} sk_hand_draw_layout;

/* The desc with zero fields replaced by their defaults. */
sk_hand_draw_desc sk_hand_draw_desc_resolved(const sk_hand_draw_desc *desc);
/* Frames `pose_count` poses (pose_count x SK_HAND_DOF_COUNT absolute DOF values) in
 * every panel at one common scale. Fit once over all frames of an animation and draw
 * each frame with the result so the frames line up. Errors name the desc field and its
 * range. `desc` may be NULL. */
sk_result sk_hand_draw_layout_fit(const sk_hand_skeleton *skeleton, const double *poses,
                                  int pose_count, const sk_hand_draw_desc *desc,
                                  sk_hand_draw_layout *layout, sk_error *err);
/* Pixel position of a world point in panel `view_index` of a layout. */
sk_vec2d sk_hand_draw_project(const sk_hand_draw_layout *layout, int view_index, sk_vec3d p);
/* Draws one pose into a newly allocated RGB image of the layout's size (free with
 * sk_image_free). `layout` NULL = fitted to this pose alone (with `desc`'s framing); a
 * layout must come from sk_hand_draw_layout_fit with the same desc (a caption, titles and
 * cues change the bands it leaves). Errors: a non-finite DOF value, a bad desc. */
sk_result sk_hand_draw(const sk_hand_skeleton *skeleton, const double dofs[SK_HAND_DOF_COUNT],
                       const sk_hand_draw_desc *desc, const sk_hand_draw_layout *layout,
                       sk_image *out, sk_error *err);
/* The colour of each finger's bones and joints in these pictures (linear RGB). */
sk_color sk_hand_finger_color(sk_hand_finger finger);

/* Draws every frame (frame_count x SK_HAND_DOF_COUNT) with one layout fitted over all of
 * them and writes "<dir>/frame_0000.png", ... (at least 4 digits; `dir` is created).
 * `captions` (NULL, or one string per frame, each may be NULL) replace desc->caption.
 * Frames are drawn in parallel; each file is written atomically. */
sk_result sk_hand_frames_write_png(const sk_hand_skeleton *skeleton, const double *dofs,
                                   int frame_count, const sk_hand_draw_desc *desc,
                                   const char *const *captions, const char *dir,
                                   sk_progress progress, sk_error *err);

/* Joint-angle plot: the angle of each listed DOF over the frames (degrees; mm for
 * translations), one line per DOF with its name in the legend. DOFs marked in `driven`
 * (may be NULL) are drawn thicker and labelled "(driven)". `plot` may be NULL (800 x 500,
 * "frame" and "angle (deg)" axis labels); its size, labels, title and ranges are used if
 * set. With an automatic y range and legend, when every corner of the plot would put the
 * legend over a line, the y range grows upward to leave it room above the data. */
sk_result sk_hand_plot_angles(const double *dofs, int frame_count, const int *dof_list,
                              int dof_count, const bool driven[SK_HAND_DOF_COUNT],
                              const sk_plot_desc *plot, sk_image *out, sk_error *err);
/* The DOFs of an animation worth plotting: the driven ones first (in DOF order), then the
 * others whose range over the frames is at least `min_range` (radians), largest range
 * first, at most `max_count` in all. Returns the count written to `out`. */
int sk_hand_moving_dofs(const double *dofs, int frame_count, const bool driven[SK_HAND_DOF_COUNT],
                        double min_range, int *out, int max_count);

/* Bar chart of an evaluation (sk_hand_evaluate): one panel per pin set, bars per joint and overall.
 * `plot` may be NULL (width 0 = 900, panel height 0 = 300; title used if set). */
sk_result sk_hand_plot_evaluation(const sk_hand_evaluation *eval, const char *model_name,
                                  const sk_plot_desc *plot, sk_image *out, sk_error *err);

#ifdef __cplusplus
}
#endif

#endif /* SHITSUKAN_HAND_PICTURES_H */
