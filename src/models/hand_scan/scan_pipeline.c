/* The whole scan-to-surface pipeline of thesis 4.1.1-4.1.4 on a surface whose truth is
 * known (or on a user's point cloud): markers on the cast, the palm and back scans, the
 * back scan registered onto the palm scan by the markers, the merged data in the hand's
 * frame with the skeleton placed in it, slices, polygons with and without the
 * neighbouring slices, 96 Bezier patches and Table 4.1; with the time of every stage. */
#include <stdlib.h>
#include <string.h>

#include "models/hand_scan/scan_internal.h"

static void report(const sk_progress *p, double f)
{
    if (p && p->fn) sk_progress_report(p, f);
}

/* The back scan: found markers -> registration -> the estimate and its error. */
static sk_result register_scans(sk_hand_scan_result *out, sk_error *err)
{
    sk_hand_registration *reg = &out->registration;
    sk_result r = sk_hand_markers_locate(&out->scan[SK_HAND_SCAN_PALM], &out->markers,
                                         reg->palm_centre, reg->palm_used, err);
    if (r == SK_OK)
        r = sk_hand_markers_locate(&out->scan[SK_HAND_SCAN_BACK], &out->markers, reg->back_centre,
                                   reg->back_used, err);
    if (r == SK_OK)
        r = sk_hand_register_rigid(reg->back_centre, reg->palm_centre, out->markers.count,
                                   &reg->back_to_palm, reg->residual_mm, err);
    if (r != SK_OK) return r;
    double sum = 0.0;
    for (int k = 0; k < out->markers.count; k++) sum += reg->residual_mm[k] * reg->residual_mm[k];
    reg->rms_mm = sqrt(sum / out->markers.count);
    sk_hand_rigid back_inv = sk_hand_rigid_inverse(&out->scan[SK_HAND_SCAN_BACK].placement);
    reg->truth = sk_hand_rigid_compose(&out->scan[SK_HAND_SCAN_PALM].placement, &back_inv);
    reg->has_truth = true;
    sk_hand_rigid_difference(&reg->back_to_palm, &reg->truth, &reg->rotation_error_deg,
                             &reg->translation_error_mm);
    return SK_OK;
}

static sk_result scan_and_merge(const sk_hand_scan_input *in, const sk_hand_scan_desc *d,
                                sk_hand_scan_result *out, const sk_progress *progress,
                                sk_error *err)
{
    double t0 = sk_time_seconds();
    /* bumps of 2.5 mm, larger if the scanner samples more coarsely than 1/3 of that */
    sk_hand_scanner_desc sr = sk_hand_scanner_desc_resolved(&d->scanner);
    double radius = d->marker_radius_mm;
    if (radius == 0) {
        radius = fmax(2.5, 3.0 * fmax(sr.size_x_mm / sr.lines, sr.size_y_mm / sr.points));
        if (radius > 10 * (1 + 1e-9))
            return sk_fail(
                err, SK_ERROR_INVALID_ARGUMENT,
                "scanner.lines = %d, scanner.points = %d: too coarse for the markers (3 sample "
                "spacings "
                "= %.3g mm, beyond their 10 mm); at least %d lines and %d points over %g x %g mm",
                sr.lines, sr.points, radius, (int)ceil(0.3 * sr.size_x_mm),
                (int)ceil(0.3 * sr.size_y_mm), sr.size_x_mm, sr.size_y_mm);
        radius = fmin(radius, 10);
    }
    sk_result r = sk_hand_markers_place(in->target, &out->frames, radius, &out->markers, err);
    sk_hand_rigid placement[SK_HAND_SCAN_SIDE_COUNT];
    if (r == SK_OK) r = sk_hand_scan_placements(in->target, &d->scanner, placement, err);
    for (int side = 0; side < SK_HAND_SCAN_SIDE_COUNT && r == SK_OK; side++) {
        r = sk_hand_scan_simulate(in->target, &out->markers, (sk_hand_scan_side)side,
                                  &placement[side], &d->scanner, d->seed, &out->scan[side], err);
        report(progress, 0.15 * (side + 1));
    }
    if (r != SK_OK) return r;
    out->scanned = true;
    double t1 = sk_time_seconds();
    out->timings.simulate = t1 - t0;
    r = register_scans(out, err);
    if (r != SK_OK) return r;
    /* the merged data in the palm scan's frame, then in the hand's: the skeleton is
       placed in it exactly where the cast lay (the thesis placed it by hand) */
    sk_hand_rigid palm_to_hand = sk_hand_rigid_inverse(&placement[SK_HAND_SCAN_PALM]);
    sk_hand_rigid back_to_hand =
        sk_hand_rigid_compose(&palm_to_hand, &out->registration.back_to_palm);
    sk_hand_rigid back_truth = sk_hand_rigid_inverse(&placement[SK_HAND_SCAN_BACK]);
    r = sk_hand_cloud_alloc(&out->cloud, 0, true, err);
    if (r == SK_OK)
        r = sk_hand_cloud_append_scan(&out->cloud, &out->scan[SK_HAND_SCAN_PALM], &out->markers,
                                      &palm_to_hand, NULL, err);
    if (r == SK_OK)
        r = sk_hand_cloud_append_scan(&out->cloud, &out->scan[SK_HAND_SCAN_BACK], &out->markers,
                                      &back_to_hand, &back_truth, err);
    out->timings.register_ = sk_time_seconds() - t1;
    report(progress, 0.35);
    return r;
}

/* Vertices of a resampled mesh against the true surface (summed in vertex order, so the
 * mean is the same for any thread count). */
static sk_result polygons_against_truth(const sk_hand_scan_target *t, const sk_mesh *m,
                                        sk_hand_resample_stats *s, sk_error *err)
{
    long long n = (long long)m->vertex_count;
    double *dist = malloc(sizeof *dist * (size_t)(n ? n : 1));
    if (!dist) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "distances of %lld vertices", n);
#pragma omp parallel for schedule(static)
    for (long long i = 0; i < n; i++) {
        const float *p = m->positions + 3 * i;
        dist[i] = sk_hand_scan_target_distance(t, sk_v3d(p[0], p[1], p[2]));
    }
    double sum = 0.0, worst = 0.0;
    for (long long i = 0; i < n; i++) {
        sum += dist[i];
        if (dist[i] > worst) worst = dist[i];
    }
    free(dist);
    s->truth_mean_mm = n ? sum / (double)n : 0.0;
    s->truth_max_mm = worst;
    return SK_OK;
}

/* Fitted to the peak resident memory at 256^2, 512^2 and 1024^2 scan points (29, 46 and
   135 MB; 112 bytes a point) and 50 and 500 slices (25 KB a slice), rounded up. */
#define SCAN_BYTES_PER_POINT 128.0
#define SCAN_BYTES_PER_SLICE 32768.0

double sk_hand_scan_memory(const sk_hand_scan_desc *desc)
{
    double lines = desc && desc->scanner.lines > 0 ? desc->scanner.lines : 512;
    double points = desc && desc->scanner.points > 0 ? desc->scanner.points : 512;
    double slices = desc && desc->slices.count > 0 ? desc->slices.count : 75;
    return SCAN_BYTES_PER_POINT * lines * points + SCAN_BYTES_PER_SLICE * slices;
}

sk_result sk_hand_scan_run(const sk_hand_scan_input *in, const sk_hand_scan_desc *desc,
                           sk_hand_scan_result *out, sk_progress progress, sk_error *err)
{
    memset(out, 0, sizeof *out);
    if (!in || !in->skeleton || !in->dofs)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "scan pipeline: no skeleton or pose given");
    if (!in->target && !in->cloud)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "scan pipeline: give a surface to scan or a point cloud");
    for (int i = 0; i < SK_HAND_DOF_COUNT; i++)
        if (!isfinite(in->dofs[i]))
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "pose: %s is not a finite number",
                           sk_hand_dof(i)->name);
    sk_hand_scan_desc d = desc ? *desc : (sk_hand_scan_desc){0};
    const sk_schema_field *splits = sk_schema_find(&sk_hand_scan_schema, "facet_splits");
    if (d.facet_splits == 0) d.facet_splits = (int)splits->def;
    sk_result r = sk_schema_check_field(splits, &d, "facet_splits", err);
    if (r != SK_OK) return r;
    double start = sk_time_seconds();
    sk_hand_forward(in->skeleton, in->dofs, &out->frames);
    sk_hand_link_geometry_from_frames(&out->frames, &out->links);
    if (in->target) {
        r = scan_and_merge(in, &d, out, &progress, err);
    } else {
        double t0 = sk_time_seconds();
        r = sk_hand_cloud_from_points(&out->cloud, in->cloud, &out->frames, err);
        out->timings.register_ = sk_time_seconds() - t0;
    }
    double t = sk_time_seconds();
    if (r == SK_OK)
        r = sk_hand_slices_build(&out->cloud, &out->links, &d.slices, &out->slices, err);
    out->timings.segment = sk_time_seconds() - t;
    report(&progress, 0.45);
    t = sk_time_seconds();
    sk_hand_resample_desc rd = d.resample;
    rd.mode = SK_HAND_RESAMPLE_NEIGHBOURS;
    if (r == SK_OK)
        r = sk_hand_resample(&out->slices, &out->links, &rd, &out->polygons, &out->polygons_stats,
                             err);
    rd.mode = SK_HAND_RESAMPLE_THESIS;
    if (r == SK_OK)
        r = sk_hand_resample(&out->slices, &out->links, &rd, &out->polygons_thesis,
                             &out->polygons_thesis_stats, err);
    out->timings.resample = sk_time_seconds() - t;
    report(&progress, 0.5);
    t = sk_time_seconds();
    if (r == SK_OK && !(out->patches = calloc(1, sizeof *out->patches)))
        r = sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "patch set");
    if (r == SK_OK) r = sk_hand_patch_layout_build(&out->cloud, &out->links, out->patches, err);
    if (r == SK_OK) r = sk_hand_patch_set_fit(out->patches, &out->cloud, &d.fit, err);
    out->timings.fit = sk_time_seconds() - t;
    report(&progress, 0.85);
    t = sk_time_seconds();
    if (r == SK_OK) r = sk_hand_patch_set_measure(out->patches, &out->cloud, d.facet_splits, err);
    if (r == SK_OK) sk_hand_table41_compute(out->patches, &out->table);
    if (r == SK_OK && in->target)
        r = polygons_against_truth(in->target, &out->polygons, &out->polygons_stats, err);
    if (r == SK_OK && in->target)
        r = polygons_against_truth(in->target, &out->polygons_thesis, &out->polygons_thesis_stats,
                                   err);
    out->timings.measure = sk_time_seconds() - t;
    out->timings.total = sk_time_seconds() - start;
    report(&progress, 1.0);
    if (r != SK_OK) sk_hand_scan_result_free(out);
    return r;
}

void sk_hand_scan_result_free(sk_hand_scan_result *result)
{
    for (int s = 0; s < SK_HAND_SCAN_SIDE_COUNT; s++) sk_hand_range_scan_free(&result->scan[s]);
    sk_hand_cloud_free(&result->cloud);
    sk_hand_slices_free(&result->slices);
    sk_mesh_free(&result->polygons);
    sk_mesh_free(&result->polygons_thesis);
    if (result->patches) {
        sk_hand_patch_set_free(result->patches);
        free(result->patches);
    }
    memset(result, 0, sizeof *result);
}

void sk_hand_scan_cast_pose(const sk_hand_skeleton *skeleton, double dofs[SK_HAND_DOF_COUNT])
{
    static const struct {
        const char *dof;
        double deg;
    } open_hand[] = {
        {"T.CMC.flex", -10}, {"T.CMC.abd", 10}, {"T.MCP.flex", 5}, {"T.IP.flex", 5},
        {"I.MCP.flex", 5},   {"I.PIP.flex", 8}, {"I.DIP.flex", 4}, {"I.MCP.abd", 6},
        {"M.MCP.flex", 5},   {"M.PIP.flex", 8}, {"M.DIP.flex", 4}, {"M.MCP.abd", 0},
        {"R.MCP.flex", 5},   {"R.PIP.flex", 8}, {"R.DIP.flex", 4}, {"R.MCP.abd", 5},
        {"L.MCP.flex", 5},   {"L.PIP.flex", 8}, {"L.DIP.flex", 4}, {"L.MCP.abd", 10},
    };
    sk_hand_relaxed(skeleton, dofs);
    for (size_t k = 0; k < sizeof open_hand / sizeof open_hand[0]; k++) {
        int d = sk_hand_dof_find(open_hand[k].dof);
        if (d >= 0) dofs[d] = open_hand[k].deg * SK_DEG_TO_RAD;
    }
    sk_hand_clamp_to_limits(skeleton, dofs);
}
