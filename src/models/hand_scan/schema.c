/* Preset schema of the scan pipeline (Yasumuro 2000, sec. 4.1): the simulated range
 * finder (4.1.1), the slices (4.1.2), the polygons' resampling (4.1.3, eqs. 4.1, 4.2), the
 * patch fit (4.1.4, eqs. 4.3-4.7) and Table 4.1's measure. Each key's range and default
 * are stated here once; the pipeline's checks read them. */
#include <stddef.h>

#include "shitsukan/hand_scan.h"

static const char *const resample_names[] = {"default", "neighbours", "thesis", NULL};

static const sk_schema_field scanner_fields[] = {
    SK_SCHEMA_INT(sk_hand_scanner_desc, lines, "lines", 8, 4096, .flags = SK_FIELD_ZERO, .def = 512,
                  .doc = "scan lines of the range finder (x = const)"),
    SK_SCHEMA_INT(sk_hand_scanner_desc, points, "points", 8, 4096, .flags = SK_FIELD_ZERO,
                  .def = 512, .doc = "points per scan line"),
    SK_SCHEMA_DOUBLE(sk_hand_scanner_desc, size_x_mm, "size_x_mm", 10, 2000, .flags = SK_FIELD_ZERO,
                     .def = 250, .doc = "extent across the lines (mm)"),
    SK_SCHEMA_DOUBLE(sk_hand_scanner_desc, size_y_mm, "size_y_mm", 10, 2000, .flags = SK_FIELD_ZERO,
                     .def = 200, .doc = "extent along a line (mm)"),
    SK_SCHEMA_DOUBLE(sk_hand_scanner_desc, size_z_mm, "size_z_mm", 10, 2000, .flags = SK_FIELD_ZERO,
                     .def = 200, .doc = "depth range (mm)"),
    SK_SCHEMA_DOUBLE(sk_hand_scanner_desc, depth_step_mm, "depth_step_mm", 1e-4, 10,
                     .flags = SK_FIELD_ZERO, .def = 0.2, .doc = "depth quantisation (mm)"),
    SK_SCHEMA_DOUBLE(sk_hand_scanner_desc, noise_mm, "noise_mm", 0, 10, .def = 0.05,
                     .doc = "depth noise sigma at normal view (mm)"),
    SK_SCHEMA_BOOL(sk_hand_scanner_desc, no_noise, "no_noise",
                   .doc = "true: no noise (noise_mm ignored)"),
    SK_SCHEMA_DOUBLE(sk_hand_scanner_desc, triangulation_deg, "triangulation_deg", 1, 80,
                     .flags = SK_FIELD_ZERO, .def = 30,
                     .doc = "camera angle off the vertical (degrees)"),
    SK_SCHEMA_DOUBLE(sk_hand_scanner_desc, grazing_deg, "grazing_deg", 10, 89.9,
                     .flags = SK_FIELD_ZERO, .def = 80,
                     .doc = "steepest measurable incidence (degrees)"),
    SK_SCHEMA_DOUBLE(sk_hand_scanner_desc, table_threshold_mm, "table_threshold_mm", 0.01, 100,
                     .flags = SK_FIELD_ZERO, .def = 1,
                     .doc = "samples at z below this are the table (mm)"),
};
const sk_schema sk_hand_scanner_schema =
    SK_SCHEMA_OF("scanner", sk_hand_scanner_desc, scanner_fields);

static const sk_schema_field slices_fields[] = {
    SK_SCHEMA_INT(sk_hand_slices_desc, count, "count", 2, 2000, .flags = SK_FIELD_ZERO, .def = 75,
                  .doc = "slice planes across the hand (75: the thesis's about 4000 polygon "
                         "vertices on the default cast)"),
    SK_SCHEMA_DOUBLE(sk_hand_slices_desc, half_thickness_mm, "half_thickness_mm", 1e-6, 50,
                     .flags = SK_FIELD_ZERO, .def = 0.5,
                     .doc = "points this near a plane are projected onto it (mm)"),
};
static const sk_schema slices_schema = SK_SCHEMA_OF("slices", sk_hand_slices_desc, slices_fields);

static const sk_schema_field resample_fields[] = {
    SK_SCHEMA_ENUM(sk_hand_resample_desc, mode, "mode", resample_names,
                   .def = SK_HAND_RESAMPLE_NEIGHBOURS,
                   .doc = "neighbours (samples alike on neighbouring slices) or thesis (each "
                          "slice alone); the pipeline makes both"),
    SK_SCHEMA_INT(sk_hand_resample_desc, points_per_segment, "points_per_segment", 3, 256,
                  .flags = SK_FIELD_ZERO, .def = 10, .doc = "points per resampled segment"),
    SK_SCHEMA_DOUBLE(sk_hand_resample_desc, arc_gap_deg, "arc_gap_deg", 5, 180,
                     .flags = SK_FIELD_ZERO, .def = 45,
                     .doc = "the palm's links: a wider gap between angles splits a slice into "
                            "arcs (degrees)"),
};
static const sk_schema resample_schema =
    SK_SCHEMA_OF("resample", sk_hand_resample_desc, resample_fields);

static const sk_schema_field fit_fields[] = {
    SK_SCHEMA_INT(sk_hand_patch_fit_desc, max_iterations, "max_iterations", 1, 10000,
                  .flags = SK_FIELD_ZERO, .def = 30, .doc = "parameter corrections at most"),
    SK_SCHEMA_DOUBLE(sk_hand_patch_fit_desc, tolerance, "tolerance", 1e-12, 0.1,
                     .flags = SK_FIELD_ZERO, .def = 1e-3,
                     .doc = "stop when no parameter moves more than this"),
    SK_SCHEMA_DOUBLE(sk_hand_patch_fit_desc, min_improvement, "min_improvement", -1, 0.5,
                     .def = 1e-3,
                     .doc = "... or when a correction lowers the RMS error by less than this "
                            "fraction (negative: never)"),
    SK_SCHEMA_BOOL(sk_hand_patch_fit_desc, no_correction, "no_correction",
                   .doc = "true: the least-squares fit of the chord-length parameters only"),
};
static const sk_schema fit_schema = SK_SCHEMA_OF("fit", sk_hand_patch_fit_desc, fit_fields);

static const sk_schema_field scan_fields[] = {
    SK_SCHEMA_OBJECT(sk_hand_scan_desc, scanner, "scanner", sk_hand_scanner_schema,
                     .doc = "the simulated laser range finder (4.1.1)"),
    SK_SCHEMA_OBJECT(sk_hand_scan_desc, slices, "slices", slices_schema,
                     .doc = "slices across the links (4.1.2)"),
    SK_SCHEMA_OBJECT(sk_hand_scan_desc, resample, "resample", resample_schema,
                     .doc = "polygons from the slices (4.1.3)"),
    SK_SCHEMA_OBJECT(sk_hand_scan_desc, fit, "fit", fit_schema,
                     .doc = "Bezier patch fit with parameter correction (4.1.4)"),
    SK_SCHEMA_INT(sk_hand_scan_desc, facet_splits, "facet_splits", 1, 1024, .flags = SK_FIELD_ZERO,
                  .def = 100, .doc = "Table 4.1's facet grid"),
    SK_SCHEMA_DOUBLE(sk_hand_scan_desc, marker_radius_mm, "marker_radius_mm", 0.5, 10,
                     .flags = SK_FIELD_ZERO,
                     .def_text = "2.5, or 3 sample spacings on a scan coarser than 0.83 mm",
                     .doc = "radius of the 9 marker bumps (mm)"),
    SK_SCHEMA_SEED(sk_hand_scan_desc, seed, "seed", .doc = "scanner noise"),
};
const sk_schema sk_hand_scan_schema = SK_SCHEMA_OF("scan", sk_hand_scan_desc, scan_fields);
