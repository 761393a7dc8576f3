/* `shitsukan sheet`: lays images out in a labelled grid (the papers' figure sheets), or
 * repeats one image edge to edge to show that it tiles without a seam. */
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "shitsukan/draw.h"

static const cli_option k_options[] = {
    {"columns", 0, "N", "grid columns; default ceil(sqrt(count))", false},
    {"tile-size", 0, "N", "scale each image to fit N x N; default: their own sizes", false},
    {"title", 0, "TEXT", "a title line above the grid", false},
    {"label", 0, "TEXT", "label of the next image, in order (repeatable)", true},
    {"text-scale", 0, "N", "text size as a multiple of the 5x9 font; default 2", false},
    {"border", 0, "N", "a thin frame of N pixels around each image; default 0", false},
    {"repeat", 0, "CxR", "instead of a grid, repeat the single image C x R times", false},
};

static bool has_suffix(const char *s, const char *suffix)
{
    size_t a = strlen(s), b = strlen(suffix);
    return a >= b && strcmp(s + a - b, suffix) == 0;
}

static sk_result read_image(const char *path, sk_image *out, sk_error *err)
{
    if (has_suffix(path, ".exr")) return sk_image_read_exr(out, path, NULL, err);
    return sk_image_read_png(out, path, NULL, NULL, NULL, err);
}

/* One image repeated cols x rows times, edge to edge. */
static sk_result repeat_image(const sk_image *src, int cols, int rows, sk_image *out, sk_error *err)
{
    sk_result r = sk_image_create(out, src->width * cols, src->height * rows, src->channels, err);
    if (r != SK_OK) return r;
    for (int ty = 0; ty < rows; ty++)
        for (int tx = 0; tx < cols; tx++) sk_draw_blit(out, src, tx * src->width, ty * src->height);
    return SK_OK;
}

static int run_sheet(const cli_command *command, const cli_args *args)
{
    const char *output = args->common.output;
    if (!output) return cli_fail(CLI_EXIT_USAGE, "sheet: -o/--output is required");
    int count = args->positional_count, status;
    const char *labels[CLI_MAX_VALUES] = {0};
    int label_count = cli_get_all(command, args, "label", labels, CLI_MAX_VALUES);
    if (label_count > count)
        return cli_fail(CLI_EXIT_USAGE, "sheet: %d labels for %d images", label_count, count);
    long long columns, tile_size, text_scale, border;
    if ((status = cli_get_int(command, args, "columns", 0, 0, 4096, &columns)) ||
        (status = cli_get_int(command, args, "tile-size", 0, 0, 16384, &tile_size)) ||
        (status = cli_get_int(command, args, "text-scale", 2, 1, 64, &text_scale)) ||
        (status = cli_get_int(command, args, "border", 0, 0, 64, &border)))
        return status;
    int rep_c = 0, rep_r = 0;
    if (cli_has(command, args, "repeat")) {
        if (count != 1) return cli_fail(CLI_EXIT_USAGE, "sheet: --repeat takes exactly one image");
        if ((status = cli_get_size(command, args, "repeat", 2, 2, 64, &rep_c, &rep_r)))
            return status;
    }

    static const char *const k_formats[] = {".png", ".exr", NULL};
    int format;
    if ((status = cli_output_format("-o", output, k_formats, &format))) return status;
    if (tile_size > 0) {
        /* every tile scaled to tile_size^2 (float RGBA) and the sheet that holds them */
        char driver[96];
        snprintf(driver, sizeof driver, "--tile-size %lld for %d image(s)", tile_size, count);
        if ((status = cli_check_memory(
                 args, 2.0 * count * cli_image_bytes(tile_size, tile_size, 16), driver)))
            return status;
    }
    sk_error err = {0};
    sk_image *images = calloc((size_t)count, sizeof *images);
    const sk_image **tiles = calloc((size_t)count, sizeof *tiles);
    sk_image sheet = {0};
    sk_result r = images && tiles ? SK_OK : SK_ERROR_OUT_OF_MEMORY;
    if (r != SK_OK) sk_fail(&err, r, "out of memory");
    double input_bytes = 0;
    for (int i = 0; i < count && r == SK_OK; i++) {
        r = read_image(args->positional[i], &images[i], &err);
        tiles[i] = &images[i];
        if (r != SK_OK) break;
        /* the inputs, the sheet (or the repeat) and its encoding, as the inputs come in */
        input_bytes += cli_image_bytes(images[i].width, images[i].height, 4.0 * images[i].channels);
        double plan = rep_c > 0 ? input_bytes * (1.0 + 1.25 * rep_c * rep_r) : 3.0 * input_bytes;
        char driver[96];
        snprintf(driver, sizeof driver, "%s %d input image(s)",
                 rep_c > 0 ? "--repeat of" : "a sheet of", i + 1);
        if ((status = cli_check_memory(args, plan, driver))) break;
    }
    if (status) {
        for (int i = 0; i < count; i++) sk_image_free(&images[i]);
        free(images);
        free(tiles);
        return status;
    }
    if (r == SK_OK && rep_c > 0) {
        r = repeat_image(&images[0], rep_c, rep_r, &sheet, &err);
    } else if (r == SK_OK) {
        sk_contact_sheet_desc desc = {.columns = (int)columns,
                                      .tile_size = (int)tile_size,
                                      .text_scale = (int)text_scale,
                                      .tile_border = (int)border,
                                      .title = cli_get(command, args, "title")};
        r = sk_contact_sheet(tiles, label_count ? labels : NULL, count, &desc, &sheet, &err);
    }
    if (r == SK_OK) r = sk_image_write_auto(&sheet, output, NULL, &err);
    sk_image_free(&sheet);
    for (int i = 0; images && i < count; i++) sk_image_free(&images[i]);
    free(images);
    free(tiles);
    return r == SK_OK ? CLI_EXIT_OK : cli_fail_error(&err);
}

const cli_command cmd_sheet = {
    .name = "sheet",
    .summary = "lay images out in a labelled grid, or repeat one to check tiling",
    .usage = "shitsukan sheet [options] IMAGE... -o OUT.png",
    .description =
        "Reads PNG or EXR images and lays them out row by row in a grid with a label under\n"
        "each and an optional title, as the papers' figures are laid out. With --repeat CxR\n"
        "it instead repeats one image edge to edge, so a seam (or its absence) shows.",
    .examples = "  shitsukan sheet --title 'Fig. 14' --columns 3 --label '(a) round 0.0' a.png \\\n"
                "      --label '(b) round 0.4' b.png --label '(c) round 1.0' c.png -o fig14.png\n"
                "  shitsukan sheet --repeat 2x2 height.png -o tiled.png",
    .options = k_options,
    .option_count = (int)(sizeof k_options / sizeof k_options[0]),
    .common = CLI_COMMON_OUTPUT | CLI_COMMON_QUIET,
    .min_positional = 1,
    .max_positional = CLI_MAX_POSITIONAL,
    .run = run_sheet,
};
