/* `shitsukan hand evaluate | synthesize` and the potential calibration behind `hand
 * calibrate`: the whole potential of eq. 3.17 fitted to joint-angle samples (thesis 3.2.2),
 * its held-out evaluation against the mean, linear regression and a PCA prior, and the
 * synthetic recordings the demonstration uses. Argument parsing only. */
#define _POSIX_C_SOURCE 200809L
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "cmd_hand_prior.h"
#include "shitsukan/hand.h"

/* ------------------------------------------------------------ samples */

int hand_read_samples(const cli_command *cmd, const cli_args *args, const char *path,
                      sk_hand_samples *out)
{
    sk_hand_samples_desc desc = {0};
    const char *units = cli_get(cmd, args, "units");
    if (units && strcmp(units, "rad") == 0)
        desc.units = SK_HAND_UNIT_RAD;
    else if (units && strcmp(units, "deg") == 0)
        desc.units = SK_HAND_UNIT_DEG;
    else if (units)
        return cli_fail(CLI_EXIT_USAGE, "--units '%s' must be rad or deg", units);
    desc.group_column = cli_get(cmd, args, "group");
    desc.ignore_columns = cli_get(cmd, args, "ignore-columns");
    sk_error err = {0};
    if (sk_hand_samples_read(path, &desc, out, &err) != SK_OK) return cli_fail_error(&err);
    if (out->units_suspect && !args->common.quiet) {
        if (desc.units == SK_HAND_UNIT_RAD)
            fprintf(stderr,
                    "shitsukan: warning: %s: angles up to %.0f read as radians look like degrees "
                    "(--units deg?)\n",
                    path, out->max_abs_angle);
        else
            fprintf(stderr,
                    "shitsukan: warning: %s: every angle is within +-%.2f, read as degrees; these "
                    "look like radians "
                    "(--units rad?)\n",
                    path, out->max_abs_angle * SK_RAD_TO_DEG);
    }
    return 0;
}

int hand_load_constraints(const char *name, const sk_hand_skeleton *skel, sk_hand_constraints *out)
{
    memset(out, 0, sizeof *out);
    if (strcmp(name, "none") == 0) return 0;
    char path[PATH_MAX];
    bool looks_like_file = strchr(name, '/') || strstr(name, ".json");
    if (looks_like_file)
        snprintf(path, sizeof path, "%s", name);
    else if (!cli_find_preset("hand", name, path, sizeof path))
        return cli_fail(CLI_EXIT_USAGE,
                        "--constraints '%s': no such set (natural, yasumuro-table-3.2, none, or a "
                        "JSON file)",
                        name);
    sk_error err = {0};
    if (sk_hand_constraints_load_file(path, skel, out, &err) != SK_OK) return cli_fail_error(&err);
    return 0;
}

int hand_poser_open(hand_poser *poser, const sk_hand_skeleton *skel, const char *potential_path,
                    const char *set_name, const sk_hand_lut *luts, int lut_count)
{
    memset(poser, 0, sizeof *poser);
    sk_error err = {0};
    if (potential_path) {
        sk_hand_potential pot;
        if (sk_hand_potential_load_file(potential_path, skel, &pot, &err) != SK_OK)
            return cli_fail_error(&err);
        sk_result r = sk_hand_potential_solver_create(&poser->potential, skel, &pot, NULL, &err);
        sk_hand_potential_free(&pot);
        return r == SK_OK ? 0 : cli_fail_error(&err);
    }
    sk_hand_constraints *c = malloc(sizeof *c);
    if (!c) return cli_fail(CLI_EXIT_RUNTIME, "out of memory");
    int rc = hand_load_constraints(set_name, skel, c);
    if (!rc && sk_hand_solver_create(&poser->solver, skel, c, luts, lut_count, NULL, &err) != SK_OK)
        rc = cli_fail_error(&err);
    free(c);
    return rc;
}

int hand_poser_solve(hand_poser *poser, const sk_hand_input *in, double *q,
                     sk_hand_solve_info *info)
{
    sk_error err = {0};
    sk_result r = poser->potential
                      ? sk_hand_potential_solve(poser->potential, in, q, info, NULL, &err)
                      : sk_hand_solve(poser->solver, in, q, info, &err);
    return r == SK_OK ? 0 : cli_fail_error(&err);
}

void hand_poser_close(hand_poser *poser)
{
    sk_hand_solver_destroy(poser->solver);
    sk_hand_potential_solver_destroy(poser->potential);
    memset(poser, 0, sizeof *poser);
}

int hand_set_prior_strength(const cli_command *cmd, const cli_args *args, sk_preset *tree)
{
    if (!cli_has(cmd, args, "prior-strength")) return 0;
    const sk_schema_field *f = cli_find_key(cmd, "potential.prior_strength");
    double strength;
    int rc = cli_get_double(cmd, args, "prior-strength", 0, 0, f->max, &strength);
    if (rc) return rc;
    char json[64];
    snprintf(json, sizeof json, "%.17g", strength == 0.0 ? -1.0 : strength); /* 0: no prior */
    return cli_set_key(tree, "potential.prior_strength", json);
}

/* The potential desc of the keys potential.* (method, components, prior_strength, seed,
 * weight_rule, weight_scale, max_pairs) and, for the method pairs, --pairs (the candidates,
 * parsed into `pairs`). */
static int potential_options(const cli_command *cmd, const cli_args *args,
                             const hand_params *params, sk_hand_potential_desc *d, int (*pairs)[2])
{
    const sk_hand_potential_desc *p = &params->potential;
    memset(d, 0, sizeof *d);
    d->method = p->method ? p->method : SK_HAND_POTENTIAL_MIXTURE;
    d->components = p->components;
    d->max_components = p->max_components;
    d->prior_strength = p->prior_strength;
    d->seed = p->seed;
    if (d->method != SK_HAND_POTENTIAL_PAIRS) {
        if (cli_has(cmd, args, "max-pairs"))
            return cli_fail(CLI_EXIT_USAGE, "--max-pairs needs --method pairs");
        return 0;
    }
    if (p->components > 1)
        return cli_fail(CLI_EXIT_USAGE,
                        "--components does not go with --method pairs (one component)");
    d->weight_rule = p->weight_rule ? p->weight_rule : SK_HAND_WEIGHT_INVERSE_VARIANCE;
    d->weight_scale = p->weight_scale;
    d->max_pairs = p->max_pairs ? p->max_pairs : (int)cli_find_key(cmd, "potential.max_pairs")->def;
    const char *text = cli_get(cmd, args, "pairs");
    if (text) {
        sk_error err = {0};
        if (sk_hand_parse_pairs(text, pairs, 64, &d->pair_count, &err) != SK_OK) {
            sk_error_prefix(&err, err.result, "--pairs");
            return cli_fail_error(&err);
        }
        d->pairs = (const int(*)[2])pairs;
    }
    return 0;
}

/* The fitted pair rows of a PAIRS potential, one line each. */
static void print_pair_rows(const sk_hand_potential *pot)
{
    const sk_hand_constraints *c = &pot->component[0].constraints;
    printf("weight scale %g; fitted rows:\n", pot->weight_scale);
    for (int k = c->row_count - pot->pair_count; k < c->row_count; k++)
        printf("  %-24s A %7.4f  W %.4g\n", c->rows[k].label, c->rows[k].coeff[0],
               c->rows[k].weight);
}

int hand_calibrate_potential(const cli_command *cmd, const cli_args *args,
                             const hand_params *params)
{
    const char *path = args->positional[0];
    if (!args->common.output) return cli_fail(CLI_EXIT_USAGE, "-o potential.json is required");
    sk_hand_potential_desc desc;
    int pairs[64][2];
    int rc = potential_options(cmd, args, params, &desc, pairs);
    if (rc) return rc;
    sk_hand_skeleton skel;
    sk_error err = {0};
    if (sk_hand_skeleton_init(&skel, NULL, &err) != SK_OK) return cli_fail_error(&err);
    sk_hand_constraints *base = malloc(sizeof *base);
    if (!base) return cli_fail(CLI_EXIT_RUNTIME, "out of memory");
    const char *base_name = cli_get(cmd, args, "base");
    rc = hand_load_constraints(base_name ? base_name : "natural", &skel, base);
    desc.base = base;
    sk_hand_samples samples = {0};
    if (!rc) rc = hand_read_samples(cmd, args, path, &samples);
    sk_hand_potential pot = {0};
    if (!rc && sk_hand_potential_fit(&pot, &skel, &samples, NULL, 0, &desc, &err) != SK_OK) {
        sk_error_prefix(&err, err.result, "%s", path);
        rc = cli_fail_error(&err);
    }
    char note[700];
    if (desc.method == SK_HAND_POTENTIAL_PAIRS)
        snprintf(note, sizeof note,
                 "fitted from %d samples of %s (prior strength %g, %d pair rows chosen on held-out "
                 "samples, weight "
                 "scale %g, base set %s)",
                 samples.count, path, pot.prior_strength, pot.pair_count, pot.weight_scale,
                 base_name ? base_name : "natural");
    else
        snprintf(note, sizeof note,
                 "fitted from %d samples of %s (prior strength %g, %d component%s, base set %s)",
                 samples.count, path, pot.prior_strength, pot.component_count,
                 pot.component_count == 1 ? "" : "s", base_name ? base_name : "natural");
    if (!rc && sk_hand_potential_write_json(&pot, note, args->common.output, &err) != SK_OK)
        rc = cli_fail_error(&err);
    if (!rc && !args->common.quiet)
        printf("%d DOFs from %d samples: %d component%s, prior strength %g, scale %.4g\n",
               pot.dof_count, samples.count, pot.component_count,
               pot.component_count == 1 ? "" : "s", pot.prior_strength, pot.scale);
    if (!rc && !args->common.quiet && desc.method == SK_HAND_POTENTIAL_PAIRS) print_pair_rows(&pot);
    sk_hand_potential_free(&pot);
    sk_hand_samples_free(&samples);
    free(base);
    return rc;
}

/* ------------------------------------------------------------ hand evaluate */

static const cli_option evaluate_options[] = {
    {"pins", 0, "A,B",
     "DOFs pinned to their measured values (the others are predicted); repeatable, one set each",
     true},
    {"folds", 0, "K",
     "hold out K contiguous blocks of samples (default 5); with --group, at most K folds of groups",
     false},
    {"group", 0, "COLUMN",
     "hold out whole groups: the CSV column naming the trial or person of each sample", false},
    {"units", 0, "UNIT", "angles of the CSV: deg (default) or rad", false},
    {"ignore-columns", 0, "A,B", "CSV columns to skip (besides frame and time)", false},
    {"model", 0, "MODEL",
     "calibrated (default), pairs (eq. 3.18 lines of --pairs), lookup-tables (3.2.3: tables of "
     "--pairs added to --base), or a fixed set: natural, yasumuro-table-3.2, none, FILE",
     false},
    {"lut-resolution", 0, "N", "lookup-tables: grid nodes per axis (default 100)", false},
    {"lut-weight", 0, "W", "lookup-tables: weight of each table (default 1)", false},
    {"lut-interp", 0, "MODE", "lookup-tables: hermite (default) or bilinear", false},
    {"method", 0, "METHOD",
     "calibrated model: mixture (default; components chosen on held-out samples), gaussian, "
     "or pairs (the thesis's form: pair rows and weight scale chosen on held-out samples)",
     false},
    {"max-pairs", 0, "N", "--method pairs: fitted rows at most (default 16)", false},
    {"components", 0, "N", "calibrated mixture: fixed component count (default: chosen)", false},
    {"prior-strength", 0, "S",
     "pseudo-samples of the base set's Gaussian (default: chosen; 0 = none)", false},
    {"base", 0, "SET", "base set: shrinkage target, springs of the pair model (default natural)",
     false},
    {"pairs", 0, "A:B,...",
     "pair model: the DOF pairs of its lines; --method pairs: the candidates (default all)", false},
    {"weights", 0, "RULE",
     "pair model: thesis (eq. 3.18, default) or inverse-variance (default of --method pairs)",
     false},
    {"weight-scale", 0, "S",
     "pair model: multiplies every weight (default 1; --method pairs: chosen)", false},
    {"pca-k", 0, "K", "components of the PCA prior baseline (default 6)", false},
    {"report", 0, "FILE.json", "write the results as JSON (one entry per pin set)", false},
    {"plot", 0, "FILE.png", "bar chart of the per-joint errors, one panel per pin set", false},
    {"plot-title", 0, "TEXT", "title of the plot", false},
};

/* --prior-strength, and --weights and --weight-scale: the pair model's (evaluation.*)
   with --model pairs, else the calibrated potential's (potential.*). */
static int evaluate_set_option_keys(const cli_command *cmd, const cli_args *args, sk_preset *tree)
{
    int rc = hand_set_prior_strength(cmd, args, tree);
    const char *model = cli_get(cmd, args, "model");
    bool pair_model = model && strcmp(model, "pairs") == 0;
    static const char *const options[] = {"weights", "weight-scale"};
    static const char *const keys[2][2] = {{"potential.weight_rule", "potential.weight_scale"},
                                           {"evaluation.weight_rule", "evaluation.weight_scale"}};
    for (int i = 0; i < 2 && !rc; i++) {
        if (!cli_has(cmd, args, options[i])) continue;
        cli_key_option o = {options[i], keys[pair_model][i], NULL, false};
        char json[128];
        rc = cli_key_option_json(cmd, &o, cli_get(cmd, args, options[i]), json, sizeof json);
        if (!rc) rc = cli_set_key(tree, o.key, json);
    }
    return rc;
}

static int evaluation_model(const cli_command *cmd, const cli_args *args, const hand_params *params,
                            const sk_hand_skeleton *skel, sk_hand_evaluation_desc *d,
                            sk_hand_constraints *fixed, sk_hand_constraints *base, int (*pairs)[2],
                            const char **model_name)
{
    const char *model = cli_get(cmd, args, "model");
    const char *base_name = cli_get(cmd, args, "base");
    int rc = hand_load_constraints(base_name ? base_name : "natural", skel, base);
    if (rc) return rc;
    rc = potential_options(cmd, args, params, &d->potential, pairs);
    if (rc) return rc;
    d->potential.base = base;
    *model_name = "model";
    if (!model || strcmp(model, "calibrated") == 0) {
        d->model = SK_HAND_EVAL_MODEL_CALIBRATED;
        return 0;
    }
    if (d->potential.method == SK_HAND_POTENTIAL_PAIRS)
        return cli_fail(CLI_EXIT_USAGE, "--method is for --model calibrated");
    bool tables = strcmp(model, "lookup-tables") == 0;
    if (strcmp(model, "pairs") == 0 || tables) {
        const char *text = cli_get(cmd, args, "pairs");
        if (!text) return cli_fail(CLI_EXIT_USAGE, "--model %s needs --pairs", model);
        sk_error err = {0};
        if (sk_hand_parse_pairs(text, pairs, 64, &d->pair_count, &err) != SK_OK) {
            sk_error_prefix(&err, err.result, "--pairs");
            return cli_fail_error(&err);
        }
        d->pairs = (const int(*)[2])pairs;
        if (tables) {
            d->model = SK_HAND_EVAL_MODEL_LUT;
            *model_name = "tables";
            d->lut = params->lut;
            return 0;
        }
        d->model = SK_HAND_EVAL_MODEL_PAIRS;
        const sk_hand_evaluation_desc *e = &params->evaluation;
        d->weight_rule = e->weight_rule ? e->weight_rule : SK_HAND_WEIGHT_THESIS;
        d->weight_scale =
            e->weight_scale ? e->weight_scale : cli_find_key(cmd, "evaluation.weight_scale")->def;
        *model_name = "pairs";
        return 0;
    }
    rc = hand_load_constraints(model, skel, fixed);
    d->model = SK_HAND_EVAL_MODEL_FIXED;
    d->fixed = fixed;
    *model_name = strlen(model) <= 10 && !strchr(model, '/') ? model : "fixed set";
    return rc;
}

static const cli_key_option evaluate_keys[] = {
    {"folds", "evaluation.folds", NULL, false},
    {"pca-k", "evaluation.pca_components", NULL, false},
    {"method", "potential.method", NULL, false},
    {"components", "potential.components", NULL, false},
    {"max-pairs", "potential.max_pairs", NULL, false},
    HAND_LUT_KEY_OPTIONS,
};

static int run_evaluate(const cli_command *cmd, const cli_args *args)
{
    const char *pin_texts[SK_HAND_EVAL_MAX_PIN_SETS + 1];
    int np = cli_get_all(cmd, args, "pins", pin_texts, SK_HAND_EVAL_MAX_PIN_SETS + 1);
    if (np == 0)
        return cli_fail(CLI_EXIT_USAGE, "--pins is required (e.g. --pins I.MCP.flex,I.PIP.flex)");
    if (np > SK_HAND_EVAL_MAX_PIN_SETS)
        return cli_fail(CLI_EXIT_USAGE, "at most %d --pins sets", SK_HAND_EVAL_MAX_PIN_SETS);
    if (cli_has(cmd, args, "plot-title") && !cli_has(cmd, args, "plot"))
        return cli_fail(CLI_EXIT_USAGE, "--plot-title needs --plot");
    sk_hand_pin_set sets[SK_HAND_EVAL_MAX_PIN_SETS];
    sk_error err = {0};
    for (int p = 0; p < np; p++)
        if (sk_hand_parse_pin_set(pin_texts[p], &sets[p], &err) != SK_OK) {
            sk_error_prefix(&err, err.result, "--pins");
            return cli_fail_error(&err);
        }
    hand_params params;
    int rc = hand_load_params(cmd, args, &params);
    if (rc) return rc;
    sk_hand_evaluation_desc desc = {0};
    desc.folds = params.evaluation.folds;
    desc.by_group = cli_has(cmd, args, "group");
    const sk_schema_field *pca = cli_find_key(cmd, "evaluation.pca_components");
    desc.pca_components =
        params.evaluation.pca_components ? params.evaluation.pca_components : (int)pca->def;
    sk_hand_skeleton skel;
    if (sk_hand_skeleton_init(&skel, NULL, &err) != SK_OK) return cli_fail_error(&err);
    /* the report and the plot appear together at the end, or neither */
    const char *report = cli_get(cmd, args, "report"), *plot = cli_get(cmd, args, "plot");
    static const char *const k_json[] = {".json", NULL}, *const k_png[] = {".png", NULL};
    const cli_output outputs[] = {{"--report", &report, k_json, false},
                                  {"--plot", &plot, k_png, false}};
    sk_output_set *written = NULL;
    if ((rc = cli_reserve_outputs(outputs, 2, &written))) return rc;
    sk_hand_constraints *fixed = malloc(sizeof *fixed), *base = malloc(sizeof *base);
    sk_hand_evaluation *eval = malloc(sizeof *eval);
    int pairs[64][2];
    const char *model_name = "model";
    sk_hand_samples samples = {0};
    if (!fixed || !base || !eval) rc = cli_fail(CLI_EXIT_RUNTIME, "out of memory");
    if (!rc)
        rc = evaluation_model(cmd, args, &params, &skel, &desc, fixed, base, pairs, &model_name);
    if (!rc) rc = hand_read_samples(cmd, args, args->positional[0], &samples);
    sk_progress_bar bar;
    if (!rc) {
        sk_progress_bar_begin(&bar, "hand evaluate", !args->common.quiet);
        desc.progress = sk_progress_bar_sink(&bar);
        sk_result r = sk_hand_evaluate(&skel, &samples, sets, np, &desc, eval, &err);
        sk_progress_bar_end(&bar);
        if (r != SK_OK) {
            sk_error_prefix(&err, r, "%s", args->positional[0]);
            rc = cli_fail_error(&err);
        }
    }
    if (!rc && report && sk_hand_evaluation_write_json(eval, report, &err) != SK_OK)
        rc = cli_fail_error(&err);
    if (!rc && plot) {
        sk_plot_desc pd = {.title = cli_get(cmd, args, "plot-title")};
        sk_image img;
        if (sk_hand_plot_evaluation(eval, model_name, &pd, &img, &err) != SK_OK)
            rc = cli_fail_error(&err);
        else {
            if (sk_image_write_png(&img, plot, NULL, &err) != SK_OK) rc = cli_fail_error(&err);
            sk_image_free(&img);
        }
    }
    for (int p = 0; !rc && p < eval->pin_set_count; p++)
        if (eval->result[p].unconverged > 0)
            fprintf(stderr,
                    "shitsukan: warning: %d of %d solves did not converge (largest residual %.2g); "
                    "their last "
                    "iterates are counted\n",
                    eval->result[p].unconverged, eval->result[p].solves,
                    eval->result[p].max_residual);
    rc = cli_finish_outputs(written, rc);
    if (!rc && !args->common.quiet) {
        sk_hand_evaluation_print(eval, model_name, stdout);
        if (desc.model == SK_HAND_EVAL_MODEL_CALIBRATED)
            printf("calibrated model: %.1f mixture component(s) on average over the folds\n",
                   eval->mean_components);
    }
    sk_hand_samples_free(&samples);
    free(fixed);
    free(base);
    free(eval);
    return rc;
}

const cli_command cmd_hand_evaluate = {
    .name = "hand evaluate",
    .summary = "held-out error of the natural-posture model against the mean, linear regression "
               "and a PCA prior",
    .usage =
        "shitsukan hand evaluate SAMPLES.csv --pins A,B [--pins C...] [--folds K | --group "
        "COLUMN]\n"
        "       [--report FILE.json] [--plot FILE.png] [--units rad|deg] [--ignore-columns A,B]",
    .description =
        "Cross-validates the model on joint-angle samples: per fold the model is calibrated on\n"
        "the other samples (the whole potential of eq. 3.17: relaxed posture, springs and rows\n"
        "from the samples' mean and precision, a mixture where it helps), each held-out sample's\n"
        "--pins DOFs are pinned to their measured values, and the model's prediction of the\n"
        "other DOFs in the CSV is compared with the measurement. Baselines on the same folds:\n"
        "the training mean, linear regression and a PCA prior with k components. Prints the RMS\n"
        "error per joint and overall (degrees); --report writes it as JSON, --plot as bars.\n"
        "--method pairs keeps the thesis's form (pair rows and weight scale chosen per fold).\n"
        "--model natural (or any set) evaluates a fixed set instead; --model pairs the thesis's\n"
        "pair lines refitted per fold (eq. 3.18 weights); --model lookup-tables the tables of\n"
        "3.2.3 built per fold. Every solve either converges or is counted as not converged\n"
        "(the table's last line, the report's \"solves\", a warning).",
    .examples = "  shitsukan hand evaluate glove.csv --pins I.MCP.flex,I.PIP.flex --pins "
                "L.MCP.flex --group person\n"
                "  shitsukan hand evaluate glove.csv --pins M.MCP.flex,M.PIP.flex --folds 10 "
                "--report eval.json --plot eval.png\n"
                "  shitsukan hand evaluate glove.csv --pins L.MCP.flex --model natural "
                "--ignore-columns trial",
    .options = evaluate_options,
    .option_count = (int)(sizeof evaluate_options / sizeof evaluate_options[0]),
    .common = CLI_COMMON_QUIET | CLI_COMMON_SEED | CLI_COMMON_PRESET | CLI_COMMON_SET,
    .min_positional = 1,
    .max_positional = 1,
    .preset_module = "hand",
    .schema = &hand_evaluate_schema,
    .run = run_evaluate,
    .key_options = evaluate_keys,
    .key_option_count = (int)(sizeof evaluate_keys / sizeof evaluate_keys[0]),
    .seed_key = "potential.seed",
    .set_option_keys = evaluate_set_option_keys,
};

/* ------------------------------------------------------------ hand synthesize */

static const cli_option synthesize_options[] = {
    {"people", 0, "N", "people in the data set (default 6)", false},
    {"trials", 0, "N", "trials per person and grasp type (default 2)", false},
    {"frames", 0, "N", "frames per trial: reach, hold, release (default 50)", false},
    {"noise", 0, "DEG", "glove noise per sample in degrees (default 2; 0 = none)", false},
};

static const cli_key_option synthesize_keys[] = {
    {"people", "synthetic.people", NULL, false},
    {"trials", "synthetic.trials", NULL, false},
    {"frames", "synthetic.frames", NULL, false},
};

/* --noise DEG: in [0, the key's maximum], 0 = none (the key's -1). */
static int synthesize_set_option_keys(const cli_command *cmd, const cli_args *args, sk_preset *tree)
{
    if (!cli_has(cmd, args, "noise")) return 0;
    double noise;
    int rc = cli_get_double(cmd, args, "noise", 0, 0, cli_find_key(cmd, "synthetic.noise_deg")->max,
                            &noise);
    char json[64];
    snprintf(json, sizeof json, "%.17g", noise > 0 ? noise : -1.0);
    return rc ? rc : cli_set_key(tree, "synthetic.noise_deg", json);
}

static int run_synthesize(const cli_command *cmd, const cli_args *args)
{
    if (!args->common.output) return cli_fail(CLI_EXIT_USAGE, "-o samples.csv is required");
    hand_params params;
    int rc = hand_load_params(cmd, args, &params);
    if (rc) return rc;
    sk_hand_synthetic_desc d = params.synthetic;
    sk_error err = {0};
    if (sk_hand_synthetic_grasps_write(&d, args->common.output, &err) != SK_OK)
        return cli_fail_error(&err);
    return 0;
}

const cli_command cmd_hand_synthesize = {
    .name = "hand synthesize",
    .summary =
        "synthetic glove recordings of finger flexion (grasp types, people, noise) for calibration",
    .usage = "shitsukan hand synthesize -o samples.csv [--people N] [--trials N] [--frames N] "
             "[--noise DEG] [--seed S]",
    .description =
        "Writes a CSV of the 12 finger flexion DOFs (index to little: MCP, PIP, DIP, degrees)\n"
        "for several people grasping ten object types in trials of reach, hold and release,\n"
        "with the couplings reported for real glove data: neighbouring PIPs strongly coupled,\n"
        "MCP and PIP of one finger weakly, the DIP a curved function of its PIP. Columns\n"
        "person and trial name each sample's person and trial (for evaluate --group). The\n"
        "file's comment lines say how it was made. It stands in for real recordings.",
    .examples = "  shitsukan hand synthesize -o grasps.csv\n"
                "  shitsukan hand synthesize --people 10 --noise 1 --seed 7 -o grasps.csv",
    .options = synthesize_options,
    .option_count = (int)(sizeof synthesize_options / sizeof synthesize_options[0]),
    .common = CLI_COMMON_OUTPUT | CLI_COMMON_SEED | CLI_COMMON_PRESET | CLI_COMMON_SET,
    .min_positional = 0,
    .max_positional = 0,
    .preset_module = "hand",
    .schema = &hand_synthesize_schema,
    .run = run_synthesize,
    .key_options = synthesize_keys,
    .key_option_count = (int)(sizeof synthesize_keys / sizeof synthesize_keys[0]),
    .seed_key = "synthetic.seed",
    .set_option_keys = synthesize_set_option_keys,
};
