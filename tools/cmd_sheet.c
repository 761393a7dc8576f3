/* `shitsukan sheet`: a contact sheet of PNG images (tiles with labels in a grid, a title
 * line), for laying out a paper's figure panels. */
#include <string.h>

#include "cli.h"
#include "shitsukan/draw.h"

static const cli_option k_options[] = {
    {"label", 0, "TEXT", "label of the next image, in order (repeatable)", true},
    {"title", 0, "TEXT", "title line above the grid", false},
    {"columns", 0, "N", "images per row; default about the square root of the count", false},
    {"tile-size", 0, "PX", "scale every image to fit PX x PX; default each at its own size", false},
    {"padding", 0, "PX", "pixels around and between cells; default 8", false},
    {"text-scale", 0, "N", "label text scale (8 px glyphs times N); default 2", false},
};

static int run_sheet(const cli_command *command, const cli_args *args)
{
    const char *output = args->common.output;
    if (!output) return cli_fail(CLI_EXIT_USAGE, "sheet: -o/--output is required");
    int count = args->positional_count;
    const char *labels[CLI_MAX_POSITIONAL] = {0};
    int label_count = cli_get_all(command, args, "label", labels, CLI_MAX_POSITIONAL);
    if (label_count > count)
        return cli_fail(CLI_EXIT_USAGE, "sheet: %d labels for %d images", label_count, count);
    long long columns, tile, padding, scale;
    int status;
    if ((status = cli_get_int(command, args, "columns", 0, 0, 4096, &columns)) ||
        (status = cli_get_int(command, args, "tile-size", 0, 0, 16384, &tile)) ||
        (status = cli_get_int(command, args, "padding", 0, 0, 1024, &padding)) ||
        (status = cli_get_int(command, args, "text-scale", 0, 0, 64, &scale)))
        return status;

    sk_image images[CLI_MAX_POSITIONAL];
    const sk_image *tiles[CLI_MAX_POSITIONAL];
    memset(images, 0, sizeof images);
    sk_error err = {0};
    sk_result r = SK_OK;
    int loaded = 0;
    for (; loaded < count && r == SK_OK; loaded++) {
        r = sk_image_read_png(&images[loaded], args->positional[loaded], NULL, NULL, NULL, &err);
        if (r != SK_OK) sk_error_prefix(&err, "%s", args->positional[loaded]);
        tiles[loaded] = &images[loaded];
    }
    sk_image sheet = {0};
    if (r == SK_OK) {
        sk_contact_sheet_desc desc = {.columns = (int)columns,
                                      .tile_size = (int)tile,
                                      .padding = (int)padding,
                                      .text_scale = (int)scale,
                                      .title = cli_get(command, args, "title")};
        r = sk_contact_sheet(tiles, labels, count, &desc, &sheet, &err);
    }
    if (r == SK_OK) {
        sk_image_metadata meta = {0};
        sk_image_metadata_set(&meta, "shitsukan:command", "sheet", NULL);
        sk_png_write_desc png = {.bit_depth = 8, .metadata = &meta};
        r = sk_image_write_png(&sheet, output, &png, &err);
    }
    for (int i = 0; i < loaded; i++) sk_image_free(&images[i]);
    sk_image_free(&sheet);
    return r == SK_OK ? CLI_EXIT_OK : cli_fail_error(&err);
}

const cli_command cmd_sheet = {
    .name = "sheet",
    .summary = "a contact sheet of PNG images with labels and a title",
    .usage = "shitsukan sheet [options] IMAGE.png... -o SHEET.png",
    .description =
        "Lays out PNG images (up to 16) row by row in a grid, each with an optional label\n"
        "under it and an optional title above the grid, on white; for a paper figure's\n"
        "panels side by side. Images are read as sRGB and the sheet is an 8-bit sRGB PNG.",
    .examples = "  shitsukan sheet a.png b.png c.png --label 'a. straight' --label 'b. spiral' \\\n"
                "      --label 'c. wavy' --title 'Fig. 5' --columns 3 -o fig5.png",
    .options = k_options,
    .option_count = (int)(sizeof k_options / sizeof k_options[0]),
    .common = CLI_COMMON_OUTPUT | CLI_COMMON_QUIET,
    .min_positional = 1,
    .max_positional = CLI_MAX_POSITIONAL,
    .run = run_sheet,
};
