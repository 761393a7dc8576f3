/* `shitsukan hand scan`: the scan-to-surface pipeline of Yasumuro's thesis (sec. 4.1) -
 * simulated range scans of the hand (or of a user's mesh), registration by the markers,
 * slices, polygons, 96 Bezier patches and Table 4.1 - writing its pictures and files into
 * a folder. Argument parsing only; the pipeline is in the library. */
#define _POSIX_C_SOURCE 200809L
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "cli.h"
#include "hand_args.h"
#include "hand_params.h"
#include "shitsukan/hand.h"
#include "shitsukan/io.h"

static const cli_option scan_options[] = {
    {"input", 0, "FILE",
     "a mesh to scan like the cast, or a point cloud taken as the registered data "
     "(OBJ or PLY, mm, in the frame of the skeleton's pose); default: the hand surface",
     false},
    {"pose", 0, "FILE",
     "the skeleton's pose in the data: a pose JSON as `hand pose -o` writes (default: the "
     "cast's open hand)",
     false},
    {"pin", 0, "DOF=DEG", "set a DOF of that pose to an absolute angle in degrees; repeatable",
     true},
    {"side", 0, "SIDE", "right (default) or left", false},
    {"hand-length", 0, "MM", "hand length, wrist crease to middle fingertip (default 190)", false},
    {"hand-breadth", 0, "MM", "hand breadth across the knuckles (default 85)", false},
    {"anatomy", 0, "FILE", "anatomy JSON (default built in)", false},
    {"lines", 0, "N", "scan lines of the range finder (default 512)", false},
    {"points", 0, "N", "points per scan line (default 512)", false},
    {"noise", 0, "MM", "depth noise sigma at normal view (default 0.05; 0 = none)", false},
    {"slices", 0, "N",
     "slice planes across the links (default 75: the thesis's about 4000 polygon vertices)", false},
    {"bend", 0, "DOF=DEG",
     "pose of patches-posed.png, added to the cast's (default: I, M, R, L MCP 40, PIP 60, "
     "DIP 30); repeatable",
     true},
    {"no-pictures", 0, NULL, "write the files only", false},
};

static int fail_error(const sk_error *err) { return cli_fail_error(err); }

/* The pose from --pose (or the cast's open hand), then --pin (each DOF at most once). */
static int read_pose(const cli_command *cmd, const cli_args *args, const sk_hand_skeleton *skel,
                     double *q)
{
    sk_hand_scan_cast_pose(skel, q);
    bool given[SK_HAND_DOF_COUNT];
    double value[SK_HAND_DOF_COUNT];
    int rc = hand_parse_dof_values(cmd, args, "pin", given, value);
    if (rc) return rc;
    const char *pose = cli_get(cmd, args, "pose");
    sk_error err = {0};
    if (pose && sk_hand_pose_load_file(pose, skel, q, &err) != SK_OK) return cli_fail_error(&err);
    for (int dof = 0; dof < SK_HAND_DOF_COUNT; dof++)
        if (given[dof]) q[dof] = value[dof];
    return 0;
}

/* --bend (each DOF at most once), or the default curl: radians (mm) added to the cast's pose
   for patches-posed.png. */
static int parse_bend(const cli_command *cmd, const cli_args *args, double bend[SK_HAND_DOF_COUNT])
{
    bool given[SK_HAND_DOF_COUNT];
    int rc = hand_parse_dof_values(cmd, args, "bend", given, bend);
    if (rc) return rc;
    bool any = false;
    for (int dof = 0; dof < SK_HAND_DOF_COUNT; dof++) {
        if (!given[dof]) bend[dof] = 0;
        any |= given[dof];
    }
    if (any) return 0;
    static const char *const fingers[] = {"I", "M", "R", "L"};
    static const char *const joints[] = {"MCP", "PIP", "DIP"};
    static const double degrees[] = {40, 60, 30};
    for (int f = 0; f < 4; f++)
        for (int j = 0; j < 3; j++) {
            char name[32];
            snprintf(name, sizeof name, "%s.%s.flex", fingers[f], joints[j]);
            int dof = sk_hand_dof_find(name);
            if (dof >= 0) bend[dof] = degrees[j] * SK_DEG_TO_RAD;
        }
    return 0;
}

static int write_png(const sk_image *img, const char *dir, const char *name)
{
    char path[PATH_MAX];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    sk_error err = {0};
    sk_png_write_desc d = {.compression_level = 3};
    return sk_image_write_png(img, path, &d, &err) == SK_OK ? 0 : fail_error(&err);
}

/* Draws with `draw` into DIR/name. */
typedef sk_result (*draw_fn)(const sk_hand_scan_result *res, sk_image *out, sk_error *err);
static int picture(const sk_hand_scan_result *res, draw_fn draw, const char *dir, const char *name)
{
    sk_image img;
    sk_error err = {0};
    if (draw(res, &img, &err) != SK_OK) return fail_error(&err);
    int rc = write_png(&img, dir, name);
    sk_image_free(&img);
    return rc;
}

static int mesh_picture(const sk_mesh *m, const char *title, const char *attr, const char *dir,
                        const char *name)
{
    sk_image img;
    sk_error err = {0};
    if (sk_hand_draw_mesh_views(m, title, attr, NULL, 0, &img, &err) != SK_OK)
        return fail_error(&err);
    int rc = write_png(&img, dir, name);
    sk_image_free(&img);
    return rc;
}

/* patches-posed.png: the patches moved to the cast's pose plus --bend (4.1.5). */
static int posed_picture(const double *bend, const sk_hand_scan_result *res,
                         const sk_hand_skeleton *skel, const double *q,
                         const sk_hand_surface *surface, const char *dir)
{
    double bent[SK_HAND_DOF_COUNT];
    for (int dof = 0; dof < SK_HAND_DOF_COUNT; dof++) bent[dof] = q[dof] + bend[dof];
    sk_hand_clamp_to_limits(skel, bent);
    sk_hand_frames pose;
    sk_hand_forward(skel, bent, &pose);
    sk_error err = {0};
    sk_hand_patch_weights *w = NULL;
    if (surface) {
        w = malloc(sizeof *w * 16 * SK_HAND_PATCH_COUNT);
        if (!w) return cli_fail(CLI_EXIT_RUNTIME, "out of memory");
        if (sk_hand_patch_weights_from_surface(surface, res->patches->patch, res->patches->count, w,
                                               &err) != SK_OK) {
            free(w);
            return fail_error(&err);
        }
    }
    sk_image img;
    sk_result r = sk_hand_draw_patches_posed(res->patches, &res->frames, &pose, w, &img, &err);
    free(w);
    if (r != SK_OK) return fail_error(&err);
    int rc = write_png(&img, dir, "patches-posed.png");
    sk_image_free(&img);
    return rc;
}

static int write_pictures(const sk_hand_scan_result *res, const sk_mesh *patch_mesh,
                          const char *dir)
{
    int rc = 0;
    for (int s = 0; s < SK_HAND_SCAN_SIDE_COUNT && res->scanned && !rc; s++) {
        sk_image img;
        sk_error err = {0};
        if (sk_hand_draw_range_scan(&res->scan[s], 1, &img, &err) != SK_OK) return fail_error(&err);
        rc = write_png(&img, dir, s == SK_HAND_SCAN_PALM ? "scan-palm.png" : "scan-back.png");
        sk_image_free(&img);
    }
    if (!rc) rc = picture(res, sk_hand_draw_registered, dir, "registered.png");
    if (!rc) rc = picture(res, sk_hand_draw_slices, dir, "slices.png");
    char title[160];
    snprintf(title, sizeof title,
             "polygons, each slice resampled alone (eqs. 4.1, 4.2): %zu vertices, %zu triangles",
             res->polygons_thesis.vertex_count, res->polygons_thesis.triangle_count);
    if (!rc) rc = mesh_picture(&res->polygons_thesis, title, "link", dir, "polygons-thesis.png");
    snprintf(title, sizeof title,
             "polygons resampled with the neighbouring slices: %zu vertices, %zu triangles",
             res->polygons.vertex_count, res->polygons.triangle_count);
    if (!rc) rc = mesh_picture(&res->polygons, title, "link", dir, "polygons.png");
    snprintf(title, sizeof title, "%d + %d Bezier patches (palm + back), one colour each",
             res->table.patches_fitted[0], res->table.patches_fitted[1]);
    if (!rc) rc = mesh_picture(patch_mesh, title, "patch", dir, "patches.png");
    return rc;
}

static int write_files(const sk_hand_scan_result *res, const sk_mesh *patch_mesh,
                       const sk_hand_surface *surface, const char *dir)
{
    char path[PATH_MAX];
    sk_error err = {0};
#define PATH(name) (snprintf(path, sizeof path, "%s/%s", dir, name), path)
    if (sk_hand_cloud_write_ply(&res->cloud, PATH("cloud.ply"), &err) != SK_OK)
        return fail_error(&err);
    if (surface && sk_mesh_write(sk_hand_surface_mesh(surface), PATH("cast.obj"), &err) != SK_OK)
        return fail_error(&err);
    if (sk_hand_table41_write_json(&res->table, PATH("table-4.1.json"), &err) != SK_OK ||
        sk_hand_table41_write_text(&res->table, PATH("table-4.1.txt"), &err) != SK_OK ||
        sk_hand_patches_write_json(res->patches, PATH("patches.json"), &err) != SK_OK ||
        sk_mesh_write(patch_mesh, PATH("patches.obj"), &err) != SK_OK ||
        sk_mesh_write(&res->polygons, PATH("polygons.obj"), &err) != SK_OK ||
        sk_mesh_write(&res->polygons_thesis, PATH("polygons-thesis.obj"), &err) != SK_OK)
        return fail_error(&err);
    if (res->scanned && sk_hand_registration_write_json(&res->registration, &res->markers,
                                                        PATH("registration.json"), &err) != SK_OK)
        return fail_error(&err);
#undef PATH
    return 0;
}

/* Only the fitted patches, tessellated 16 x 16. */
static int tessellate(const sk_hand_scan_result *res, sk_mesh *out)
{
    sk_hand_patch fitted[SK_HAND_PATCH_COUNT];
    int n = 0;
    for (int k = 0; k < res->patches->count; k++)
        if (res->patches->fitted[k]) fitted[n++] = res->patches->patch[k];
    sk_error err = {0};
    if (n == 0) return cli_fail(CLI_EXIT_USAGE, "no patch had enough points to be fitted");
    if (sk_hand_patches_tessellate(fitted, n, 16, out, &err) != SK_OK) return fail_error(&err);
    return 0;
}

static void print_summary(const sk_hand_scan_result *res)
{
    if (res->scanned) {
        printf("registration (back scan onto palm scan, 9 markers): rms %.4f mm, rotation error "
               "%.4f deg, "
               "translation error %.4f mm\n",
               res->registration.rms_mm, res->registration.rotation_error_deg,
               res->registration.translation_error_mm);
        for (int k = 0; k < res->markers.count; k++)
            printf("  %-16s residual %.4f mm  (%d palm, %d back samples)\n", res->markers.name[k],
                   res->registration.residual_mm[k], res->registration.palm_used[k],
                   res->registration.back_used[k]);
    }
    printf("cloud: %zu points; polygons: %zu vertices, %zu triangles (fold %.1f deg, %.3f mm from "
           "the truth; slice by "
           "slice: %.1f deg, %.3f mm)\n",
           res->cloud.count, res->polygons.vertex_count, res->polygons.triangle_count,
           res->polygons_stats.fold_mean_deg, res->polygons_stats.truth_mean_mm,
           res->polygons_thesis_stats.fold_mean_deg, res->polygons_thesis_stats.truth_mean_mm);
    const sk_hand_table41 *t = &res->table;
    printf("Table 4.1 [mm]      thesis mean / max   scan mean / max     truth mean / max\n");
    static const char *const names[2] = {"palm", "back"};
    static const double thesis[2][2] = {{SK_HAND_THESIS_PALM_MEAN_MM, SK_HAND_THESIS_PALM_MAX_MM},
                                        {SK_HAND_THESIS_BACK_MEAN_MM, SK_HAND_THESIS_BACK_MAX_MM}};
    for (int s = 0; s < 2; s++) {
        printf("  %-4s (%2d patches) %8.3f / %-8.3g %8.4f / %-8.3g", names[s], t->patches_fitted[s],
               thesis[s][0], thesis[s][1], t->scan[s].mean_mm, t->scan[s].max_mm);
        if (t->has_truth) printf(" %8.4f / %-8.3g", t->truth[s].mean_mm, t->truth[s].max_mm);
        printf("\n");
    }
    const sk_hand_scan_timings *tm = &res->timings;
    printf("time: simulate %.2f s, register %.2f s, segment %.2f s, resample %.2f s, fit %.2f s, "
           "measure %.2f s, "
           "total %.2f s\n",
           tm->simulate, tm->register_, tm->segment, tm->resample, tm->fit, tm->measure, tm->total);
}

static int scan(const cli_command *cmd, const cli_args *args, const sk_hand_skeleton *pose_skel,
                const double *q, const sk_hand_scan_desc *scan_desc, const double *bend,
                const char *dir);

static const cli_key_option scan_keys[] = {
    HAND_SKELETON_KEY_OPTIONS,
    {"slices", "scan.slices.count", NULL, false},
};

/* --lines N, --points N: the scanner's counts, at least 0.3 a mm over its default extent
   (the markers: see check_marker_spacing); --noise MM: scan.scanner.noise_mm in its range,
   0 = none (scan.scanner.no_noise). */
static int scan_set_option_keys(const cli_command *cmd, const cli_args *args, sk_preset *tree)
{
    sk_hand_scanner_desc s = sk_hand_scanner_desc_resolved(NULL);
    const char *options[2] = {"lines", "points"};
    const char *keys[2] = {"scan.scanner.lines", "scan.scanner.points"};
    double sizes[2] = {s.size_x_mm, s.size_y_mm};
    char json[64];
    int rc = 0;
    for (int i = 0; i < 2 && !rc; i++) {
        if (!cli_has(cmd, args, options[i])) continue;
        const sk_schema_field *f = cli_find_key(cmd, keys[i]);
        long long n, least = (long long)ceil(0.3 * sizes[i]);
        rc = cli_get_int(cmd, args, options[i], 0, least > f->min ? least : (long long)f->min,
                         (long long)f->max, &n);
        snprintf(json, sizeof json, "%lld", n);
        if (!rc) rc = cli_set_key(tree, keys[i], json);
    }
    if (rc || !cli_has(cmd, args, "noise")) return rc;
    const sk_schema_field *f = cli_find_key(cmd, "scan.scanner.noise_mm");
    double noise;
    rc = cli_get_double(cmd, args, "noise", 0, f->min, f->max, &noise);
    snprintf(json, sizeof json, "%.17g", noise);
    if (!rc) rc = cli_set_key(tree, "scan.scanner.noise_mm", json);
    if (!rc) rc = cli_set_key(tree, "scan.scanner.no_noise", noise == 0 ? "true" : "false");
    return rc;
}

/* The markers are 3 sample spacings wide, at most 10 mm: a coarsest scan follows (at least
   0.3 samples a mm across the lines and along them). */
static int check_marker_spacing(const cli_command *cmd, const cli_args *args,
                                const sk_hand_scanner_desc *given)
{
    sk_hand_scanner_desc s = sk_hand_scanner_desc_resolved(given);
    const char *options[2] = {"lines", "points"}, *keys[2] = {"lines", "points"};
    int counts[2] = {s.lines, s.points};
    double sizes[2] = {s.size_x_mm, s.size_y_mm};
    for (int i = 0; i < 2; i++) {
        long long least = (long long)ceil(0.3 * sizes[i]);
        if (counts[i] >= least) continue;
        long long most = (long long)cli_find_key(cmd, "scan.scanner.lines")->max;
        if (cli_has(cmd, args, options[i]))
            return cli_fail(CLI_EXIT_USAGE, "--%s '%s' must be an integer in [%lld, %lld]",
                            options[i], cli_get(cmd, args, options[i]), least, most);
        return cli_fail(CLI_EXIT_USAGE,
                        "scan.scanner.%s = %d: the markers need at least %lld over %g mm (0.3 a "
                        "mm)",
                        keys[i], counts[i], least, sizes[i]);
    }
    return 0;
}

static int run_scan(const cli_command *cmd, const cli_args *args)
{
    const char *dir = args->common.output;
    if (!dir)
        return cli_fail(CLI_EXIT_USAGE,
                        "-o DIR is required (the folder for the pictures and files)");
    hand_params params;
    int rc = hand_load_params(cmd, args, &params);
    if (rc) return rc;
    sk_hand_skeleton skel;
    rc = hand_build_skeleton(cmd, args, &params.hand, SK_HAND_SIDE_RIGHT, 0, 0, &skel);
    double q[SK_HAND_DOF_COUNT];
    if (!rc) rc = read_pose(cmd, args, &skel, q);
    if (!rc) rc = check_marker_spacing(cmd, args, &params.scan.scanner);
    if (rc) return rc;
    sk_hand_scan_desc d = params.scan;
    const char *input = cli_get(cmd, args, "input");
    bool pictures = !cli_has(cmd, args, "no-pictures");
    double bend[SK_HAND_DOF_COUNT];
    if (!pictures && cli_has(cmd, args, "bend"))
        return cli_fail(CLI_EXIT_USAGE, "--bend poses patches-posed.png: not with --no-pictures");
    if ((rc = parse_bend(cmd, args, bend))) return rc;
    /* the scans and slices, and the cast's surface or the input mesh (16 bytes per byte of
       its file, as the renderer counts) */
    struct stat st;
    double bytes =
        sk_hand_scan_memory(&d) + (input ? (stat(input, &st) == 0 ? 16.0 * (double)st.st_size : 0)
                                         : sk_hand_surface_memory(&skel, NULL));
    if ((rc = cli_check_memory(
             args, bytes,
             input ? "hand scan (--lines x --points, --slices, and --input's mesh)"
                   : "hand scan (--lines x --points, --slices, and the cast's surface)")))
        return rc;
    /* every file appears in DIR at the end, or none */
    const cli_output outputs[] = {{"-o", &dir, NULL, true}};
    sk_output_set *written = NULL;
    if ((rc = cli_reserve_outputs(outputs, 1, &written))) return rc;
    rc = scan(cmd, args, &skel, q, &d, bend, dir);
    return cli_finish_outputs(written, rc);
}

/* The pipeline, writing into `dir` (the staged folder). */
static int scan(const cli_command *cmd, const cli_args *args, const sk_hand_skeleton *pose_skel,
                const double *q, const sk_hand_scan_desc *scan_desc, const double *bend,
                const char *dir)
{
    const char *input = cli_get(cmd, args, "input");
    sk_hand_skeleton skel = *pose_skel;
    sk_hand_scan_desc d = *scan_desc;
    int rc = 0;
    sk_error err = {0};
    sk_mesh mesh = {0};
    sk_hand_scan_target *target = NULL;
    sk_hand_surface *surface = NULL;
    sk_hand_skeleton cast;
    sk_hand_scan_input in = {.skeleton = &skel, .dofs = q};
    double t_surface = sk_time_seconds();
    if (!input) {
        /* the cast: the hand surface meshed in the pose */
        if (sk_hand_scan_cast(&skel, q, NULL, &cast, &surface, &target, &err) != SK_OK)
            return fail_error(&err);
        in.skeleton = &cast;
        in.target = target;
    } else {
        if (sk_mesh_read(&mesh, input, NULL, &err) != SK_OK) return fail_error(&err);
        if (mesh.triangle_count > 0) {
            sk_hand_scan_target_desc td = {.mesh = &mesh};
            if (sk_hand_scan_target_create(&target, &td, &err) != SK_OK) {
                sk_error_prefix(&err, err.result, "%s", input);
                sk_mesh_free(&mesh);
                return fail_error(&err);
            }
            in.target = target;
        } else {
            in.cloud = &mesh;
        }
    }
    t_surface = sk_time_seconds() - t_surface;
    sk_hand_scan_result res;
    sk_progress_bar bar;
    if (!rc) {
        sk_progress_bar_begin(&bar, "hand scan", !args->common.quiet);
        sk_result r = sk_hand_scan_run(&in, &d, &res, sk_progress_bar_sink(&bar), &err);
        sk_progress_bar_end(&bar);
        if (r != SK_OK) {
            if (input) sk_error_prefix(&err, err.result, "%s", input);
            rc = fail_error(&err);
        }
    }
    sk_hand_scan_target_destroy(target);
    sk_mesh_free(&mesh);
    if (rc) {
        sk_hand_surface_destroy(surface);
        return rc;
    }
    sk_mesh patch_mesh = {0};
    rc = tessellate(&res, &patch_mesh);
    if (!rc) rc = write_files(&res, &patch_mesh, surface, dir);
    if (!rc && !cli_has(cmd, args, "no-pictures")) rc = write_pictures(&res, &patch_mesh, dir);
    if (!rc && !cli_has(cmd, args, "no-pictures"))
        rc = posed_picture(bend, &res, in.skeleton, q, surface, dir);
    if (!rc && !args->common.quiet) {
        if (!input) printf("hand surface (the cast) meshed in %.2f s\n", t_surface);
        print_summary(&res);
    }
    sk_mesh_free(&patch_mesh);
    sk_hand_scan_result_free(&res);
    sk_hand_surface_destroy(surface);
    return rc;
}

const cli_command cmd_hand_scan = {
    .name = "hand scan",
    .summary = "the thesis's scan-to-surface pipeline: range scans, registration, slices, "
               "polygons, Bezier patches, "
               "Table 4.1",
    .usage = "shitsukan hand scan [--input cloud.ply|mesh.obj] [--pose pose.json] [--pin "
             "DOF=DEG]... -o DIR",
    .description =
        "Reproduces sec. 4.1 of Yasumuro's thesis. A mesh (the hand surface, or --input) is "
        "scanned\n"
        "like the plaster cast by a simulated laser range finder (512 lines x 512 points over\n"
        "250 x 200 x 200 mm, depth in 0.2 mm steps, noise, occlusion, the table removed by a "
        "depth\n"
        "threshold), palm up and turned over, with 9 marker bumps; the back scan is registered "
        "onto\n"
        "the palm scan by least squares on the markers; 75 slices across the links (the thesis:\n"
        "about 50) give polygons of about 4000 vertices (eqs. 4.1, 4.2, slice by slice as in the\n"
        "thesis and with the neighbouring slices); 48 + 48 bicubic Bezier patches are fitted by\n"
        "least squares with parameter correction (eqs. 4.3-4.7), and their error is measured as "
        "in\n"
        "Table 4.1, against the scan and against the true surface. A point cloud as --input is "
        "taken as the registered data.\n"
        "The skeleton's pose in the data is the cast's open hand, or --pose, changed with --pin;\n"
        "an --input must be in that skeleton's frame (mm; X radial, Y distal, Z palmar).\n"
        "Writes into DIR: table-4.1.txt/.json, registration.json, patches.json (control points),\n"
        "patches.obj, polygons.obj, polygons-thesis.obj, cloud.ply (the registered data, with\n"
        "its scan side), cast.obj (the scanned hand surface), and the pictures scan-palm.png,\n"
        "scan-back.png, registered.png, slices.png, polygons.png, polygons-thesis.png, "
        "patches.png,\n"
        "patches-posed.png (the control points moving with their links: rigid, and with the\n"
        "surface's smooth weights).",
    .examples = "  shitsukan hand scan --input hand.obj -o scan\n"
                "  shitsukan hand scan --input cloud.ply --pose pose.json --pin I.MCP.flex=20 -o "
                "scan --no-pictures",
    .options = scan_options,
    .option_count = (int)(sizeof scan_options / sizeof scan_options[0]),
    .common = CLI_COMMON_OUTPUT | CLI_COMMON_SEED | CLI_COMMON_THREADS | CLI_COMMON_QUIET |
              CLI_COMMON_PRESET | CLI_COMMON_SET,
    .min_positional = 0,
    .max_positional = 0,
    .preset_module = "hand",
    .schema = &hand_scan_schema,
    .run = run_scan,
    .key_options = scan_keys,
    .key_option_count = (int)(sizeof scan_keys / sizeof scan_keys[0]),
    .seed_key = "scan.seed",
    .set_option_keys = scan_set_option_keys,
};
