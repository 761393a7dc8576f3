/* Contact sheets: tiles laid out in a grid with a centred label per tile and an optional
 * title, as used for the paper-figure layouts ("(a) jitter 0.0", "(b) ..."). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "products/draw/draw_internal.h"

#define SK__SHEET_MAX_COUNT 65536

sk_contact_sheet_desc sk_contact_sheet_desc_resolved(const sk_contact_sheet_desc *desc, int count)
{
    sk_contact_sheet_desc d = {0};
    if (desc) d = *desc;
    if (d.columns == 0) {
        int c = 1;
        while (c < count && (long long)c * c < count) c++;
        d.columns = c;
    }
    if (d.padding == 0) d.padding = 8;
    if (d.text_scale == 0) d.text_scale = 2;
    if (d.title_scale == 0) d.title_scale = d.text_scale + 1;
    if (sk__color_is_zero(d.background)) d.background = sk_rgba(1.0f, 1.0f, 1.0f, 1.0f);
    if (sk__color_is_zero(d.text_color)) d.text_color = sk_rgba(0.0f, 0.0f, 0.0f, 1.0f);
    if (d.channels == 0) d.channels = 3;
    if (d.label_position == SK_LABEL_DEFAULT) d.label_position = SK_LABEL_BELOW;
    return d;
}

static sk_result check_color(sk_error *err, const char *name, sk_color c)
{
    if (!sk__color_finite(c))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "%s = {%g, %g, %g, %g} has a component that is not a finite number", name,
                       (double)c.r, (double)c.g, (double)c.b, (double)c.a);
    return SK_OK;
}

static sk_result validate(const sk_image *const *tiles, int count, const sk_contact_sheet_desc *d,
                          sk_error *err)
{
    sk_result r;
    if ((r = sk_check_range_i(err, "count", count, 1, SK__SHEET_MAX_COUNT)) != SK_OK) return r;
    if (!tiles) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "tiles is NULL");
    if ((r = sk_check_range_i(err, "columns", d->columns, 0, 4096)) != SK_OK) return r;
    if ((r = sk_check_range_i(err, "tile_size", d->tile_size, 0, 16384)) != SK_OK) return r;
    if ((r = sk_check_range_i(err, "padding", d->padding, 0, 1024)) != SK_OK) return r;
    if ((r = sk_check_range_i(err, "text_scale", d->text_scale, 0, SK__MAX_TEXT_SCALE)) != SK_OK)
        return r;
    if ((r = sk_check_range_i(err, "title_scale", d->title_scale, 0, SK__MAX_TEXT_SCALE)) != SK_OK)
        return r;
    if ((r = sk_check_range_i(err, "channels", d->channels, 0, 4)) != SK_OK) return r;
    if ((r = sk_check_range_i(err, "label_position", (int)d->label_position, 0, SK_LABEL_ABOVE)) !=
        SK_OK)
        return r;
    if ((r = sk_check_range_i(err, "tile_filter", (int)d->tile_filter, 0, SK_RESIZE_BOX)) != SK_OK)
        return r;
    if ((r = sk_check_range_i(err, "tile_border", d->tile_border, 0, 64)) != SK_OK) return r;
    if ((r = check_color(err, "background", d->background)) != SK_OK) return r;
    if ((r = check_color(err, "text_color", d->text_color)) != SK_OK) return r;
    for (int i = 0; i < count; i++) {
        char name[32];
        snprintf(name, sizeof name, "tiles[%d]", i);
        if ((r = sk__image_check(tiles[i], name, err)) != SK_OK) return r;
    }
    return SK_OK;
}

/* The size a tile is shown at: its own, or scaled (aspect kept) to fit tile_size. */
static void shown_size(const sk_image *tile, int tile_size, int *w, int *h)
{
    if (tile_size <= 0) {
        *w = tile->width;
        *h = tile->height;
        return;
    }
    double s = fmin((double)tile_size / tile->width, (double)tile_size / tile->height);
    *w = (int)fmax(1.0, floor(tile->width * s + 0.5));
    *h = (int)fmax(1.0, floor(tile->height * s + 0.5));
}

static bool has_text(const char *s) { return s && s[0]; }

sk_result sk_contact_sheet(const sk_image *const *tiles, const char *const *labels, int count,
                           const sk_contact_sheet_desc *desc, sk_image *out, sk_error *err)
{
    if (!out) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "contact sheet: out is NULL");
    sk_contact_sheet_desc raw = {0};
    if (desc) raw = *desc;
    sk_result r = validate(tiles, count, &raw, err);
    if (r != SK_OK) return r;
    sk_contact_sheet_desc d = sk_contact_sheet_desc_resolved(&raw, count);
    int columns = d.columns < count ? d.columns : count;
    int rows = (count + columns - 1) / columns;
    int pad = d.padding;

    /* Cell sizes (long long: nothing here can overflow before the limit check). */
    long long cell_w = 1, cell_h = 1;
    bool any_label = false;
    for (int i = 0; i < count; i++) {
        int w, h;
        shown_size(tiles[i], d.tile_size, &w, &h);
        if (w > cell_w) cell_w = w;
        if (h > cell_h) cell_h = h;
        if (labels && has_text(labels[i])) {
            any_label = true;
            /* One glyph advance of air between neighbouring labels (beyond the padding). */
            long long lw = (long long)sk_draw_text_width(labels[i], d.text_scale) +
                           SK__GLYPH_ADVANCE * d.text_scale;
            if (lw > cell_w) cell_w = lw;
        }
    }
    long long text_h = sk_draw_text_height(d.text_scale);
    long long label_gap = (pad + 1) / 2;
    long long label_band = any_label ? text_h + label_gap : 0;
    bool titled = has_text(d.title);
    long long title_w = titled ? sk_draw_text_width(d.title, d.title_scale) : 0;
    long long title_band = titled ? sk_draw_text_height(d.title_scale) + pad : 0;
    long long grid_w = pad + (long long)columns * (cell_w + pad);
    long long sheet_w = grid_w;
    if (titled && title_w + 2LL * pad > sheet_w) sheet_w = title_w + 2LL * pad;
    long long sheet_h = pad + title_band + (long long)rows * (cell_h + label_band + pad);
    if (sheet_w > SK_IMAGE_MAX_DIMENSION || sheet_h > SK_IMAGE_MAX_DIMENSION)
        return sk_fail(err, SK_ERROR_LIMIT,
                       "contact sheet would be %lld x %lld pixels, over the limit of %d per side "
                       "(reduce tile_size, columns, padding or text_scale)",
                       sheet_w, sheet_h, SK_IMAGE_MAX_DIMENSION);
    sk_image sheet = {0};
    r = sk__image_alloc(&sheet, (int)sheet_w, (int)sheet_h, d.channels, "contact sheet", err);
    if (r != SK_OK) return r;
    sk_draw_clear(&sheet, d.background);

    if (titled)
        sk_draw_text(&sheet, (float)((sheet_w - title_w) / 2), (float)pad, d.title, d.title_scale,
                     d.text_color);
    long long grid_x = (sheet_w - grid_w) / 2;
    for (int i = 0; i < count; i++) {
        long long cx = grid_x + pad + (long long)(i % columns) * (cell_w + pad);
        long long cy = pad + title_band + (long long)(i / columns) * (cell_h + label_band + pad);
        long long tile_y = d.label_position == SK_LABEL_ABOVE ? cy + label_band : cy;
        long long label_y = d.label_position == SK_LABEL_ABOVE ? cy : cy + cell_h + label_gap;
        int w, h;
        shown_size(tiles[i], d.tile_size, &w, &h);
        int tx = (int)(cx + (cell_w - w) / 2), ty = (int)(tile_y + (cell_h - h) / 2);
        if (w == tiles[i]->width && h == tiles[i]->height) {
            sk_draw_blit(&sheet, tiles[i], tx, ty);
        } else {
            sk_image scaled;
            r = sk_image_resize_filter(tiles[i], w, h, d.tile_filter, &scaled, err);
            if (r != SK_OK) {
                free(sheet.data);
                return sk_error_prefix(err, r, "tiles[%d]", i);
            }
            sk_draw_blit(&sheet, &scaled, tx, ty);
            free(scaled.data);
        }
        if (d.tile_border > 0) {
            /* four bars just outside the tile, so its pixels are never covered */
            float b = (float)d.tile_border;
            sk_color c = d.text_color;
            c.a *= 0.5f;
            sk_draw_rect(&sheet, (float)tx - b, (float)ty - b, (float)w + 2 * b, b, c);
            sk_draw_rect(&sheet, (float)tx - b, (float)(ty + h), (float)w + 2 * b, b, c);
            sk_draw_rect(&sheet, (float)tx - b, (float)ty, b, (float)h, c);
            sk_draw_rect(&sheet, (float)(tx + w), (float)ty, b, (float)h, c);
        }
        if (labels && has_text(labels[i])) {
            long long lw = sk_draw_text_width(labels[i], d.text_scale);
            sk_draw_text(&sheet, (float)(cx + (cell_w - lw) / 2), (float)label_y, labels[i],
                         d.text_scale, d.text_color);
        }
    }
    *out = sheet;
    return SK_OK;
}
