/**
 * @file demo_raster.c
 * @brief Host-side picture writer for the char_body example (see demo_raster.h).
 */
#include "demo_raster.h"
#include <math.h>
#include <png.h>
#include <stdio.h>
#include <stdlib.h>

bool img_init(img_t *im, int w, int h, uint32_t rgba)
{
    im->w = w;
    im->h = h;
    im->rgb = malloc((size_t)w * (size_t)h * 3u);
    if (!im->rgb) return false;
    for (int i = 0; i < w * h; i++) {
        im->rgb[3 * i + 0] = (uint8_t)(rgba >> 24);
        im->rgb[3 * i + 1] = (uint8_t)(rgba >> 16);
        im->rgb[3 * i + 2] = (uint8_t)(rgba >> 8);
    }
    return true;
}

void img_free(img_t *im)
{
    free(im->rgb);
    im->rgb = NULL;
}

void img_blend(img_t *im, int x, int y, uint32_t rgba, float cover)
{
    if (x < 0 || y < 0 || x >= im->w || y >= im->h) return;
    float a = (float)(rgba & 0xFFu) / 255.0f * cover;
    if (a <= 0.0f) return;
    if (a > 1.0f) a = 1.0f;
    uint8_t *p = &im->rgb[3 * ((size_t)y * (size_t)im->w + (size_t)x)];
    for (int c = 0; c < 3; c++) {
        float src = (float)((rgba >> (24 - 8 * c)) & 0xFFu);
        p[c] = (uint8_t)lrintf((float)p[c] + (src - (float)p[c]) * a);
    }
}

/* Distance-based anti-aliased thick line: coverage from the distance to the segment. */
void img_line(img_t *im, float x0, float y0, float x1, float y1, uint32_t rgba, float width)
{
    if (!isfinite(x0) || !isfinite(y0) || !isfinite(x1) || !isfinite(y1)) return;
    float hw = 0.5f * width;
    int xa = (int)floorf(fminf(x0, x1) - hw - 1.0f), xb = (int)ceilf(fmaxf(x0, x1) + hw + 1.0f);
    int ya = (int)floorf(fminf(y0, y1) - hw - 1.0f), yb = (int)ceilf(fmaxf(y0, y1) + hw + 1.0f);
    if (xa < 0) xa = 0;
    if (ya < 0) ya = 0;
    if (xb > im->w - 1) xb = im->w - 1;
    if (yb > im->h - 1) yb = im->h - 1;
    if (xa > xb || ya > yb) return;
    float dx = x1 - x0, dy = y1 - y0, l2 = dx * dx + dy * dy;
    for (int y = ya; y <= yb; y++) {
        for (int x = xa; x <= xb; x++) {
            float px = (float)x + 0.5f - x0, py = (float)y + 0.5f - y0;
            float t = l2 > 0.0f ? (px * dx + py * dy) / l2 : 0.0f;
            if (t < 0.0f) t = 0.0f;
            if (t > 1.0f) t = 1.0f;
            float ex = px - t * dx, ey = py - t * dy;
            float d = sqrtf(ex * ex + ey * ey);
            float cover = hw + 0.5f - d;
            if (cover <= 0.0f) continue;
            img_blend(im, x, y, rgba, cover > 1.0f ? 1.0f : cover);
        }
    }
}

void img_tri(img_t *im, float x0, float y0, float x1, float y1, float x2, float y2, uint32_t rgba)
{
    float area = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0);
    if (!(fabsf(area) > 1e-6f)) return;
    if (area < 0.0f) { float t = x1; x1 = x2; x2 = t; t = y1; y1 = y2; y2 = t; area = -area; }
    int xa = (int)floorf(fminf(x0, fminf(x1, x2))), xb = (int)ceilf(fmaxf(x0, fmaxf(x1, x2)));
    int ya = (int)floorf(fminf(y0, fminf(y1, y2))), yb = (int)ceilf(fmaxf(y0, fmaxf(y1, y2)));
    if (xa < 0) xa = 0;
    if (ya < 0) ya = 0;
    if (xb > im->w - 1) xb = im->w - 1;
    if (yb > im->h - 1) yb = im->h - 1;
    for (int y = ya; y <= yb; y++) {
        for (int x = xa; x <= xb; x++) {
            float px = (float)x + 0.5f, py = (float)y + 0.5f;
            float w0 = (x1 - px) * (y2 - py) - (x2 - px) * (y1 - py);
            float w1 = (x2 - px) * (y0 - py) - (x0 - px) * (y2 - py);
            float w2 = (x0 - px) * (y1 - py) - (x1 - px) * (y0 - py);
            if (w0 >= 0.0f && w1 >= 0.0f && w2 >= 0.0f) img_blend(im, x, y, rgba, 1.0f);
        }
    }
}

void img_disc(img_t *im, float cx, float cy, float r, uint32_t rgba)
{
    for (int y = (int)floorf(cy - r - 1.0f); y <= (int)ceilf(cy + r + 1.0f); y++)
        for (int x = (int)floorf(cx - r - 1.0f); x <= (int)ceilf(cx + r + 1.0f); x++) {
            float dx = (float)x + 0.5f - cx, dy = (float)y + 0.5f - cy;
            float cover = r + 0.5f - sqrtf(dx * dx + dy * dy);
            if (cover > 0.0f) img_blend(im, x, y, rgba, cover > 1.0f ? 1.0f : cover);
        }
}

void img_rect(img_t *im, int x0, int y0, int x1, int y1, uint32_t rgba)
{
    for (int y = y0; y < y1; y++)
        for (int x = x0; x < x1; x++) img_blend(im, x, y, rgba, 1.0f);
}

static const char font_chars[] = " %\'()+,-./0123456789:=ABCDEFGHIJKLMNOPQRSTUVWXYZ_";
static const uint8_t font_rows[][7] = {
    {0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00}, /*   */
    {0x18, 0x19, 0x02, 0x04, 0x08, 0x13, 0x03}, /* % */
    {0x0c, 0x04, 0x08, 0x00, 0x00, 0x00, 0x00}, /* ' */
    {0x02, 0x04, 0x08, 0x08, 0x08, 0x04, 0x02}, /* ( */
    {0x08, 0x04, 0x02, 0x02, 0x02, 0x04, 0x08}, /* ) */
    {0x00, 0x04, 0x04, 0x1f, 0x04, 0x04, 0x00}, /* + */
    {0x00, 0x00, 0x00, 0x00, 0x0c, 0x04, 0x08}, /* , */
    {0x00, 0x00, 0x00, 0x1f, 0x00, 0x00, 0x00}, /* - */
    {0x00, 0x00, 0x00, 0x00, 0x00, 0x0c, 0x0c}, /* . */
    {0x00, 0x01, 0x02, 0x04, 0x08, 0x10, 0x00}, /* / */
    {0x0e, 0x11, 0x13, 0x15, 0x19, 0x11, 0x0e}, /* 0 */
    {0x04, 0x0c, 0x04, 0x04, 0x04, 0x04, 0x0e}, /* 1 */
    {0x0e, 0x11, 0x01, 0x02, 0x04, 0x08, 0x1f}, /* 2 */
    {0x1f, 0x02, 0x04, 0x02, 0x01, 0x11, 0x0e}, /* 3 */
    {0x02, 0x06, 0x0a, 0x12, 0x1f, 0x02, 0x02}, /* 4 */
    {0x1f, 0x10, 0x1e, 0x01, 0x01, 0x11, 0x0e}, /* 5 */
    {0x06, 0x08, 0x10, 0x1e, 0x11, 0x11, 0x0e}, /* 6 */
    {0x1f, 0x01, 0x02, 0x04, 0x08, 0x08, 0x08}, /* 7 */
    {0x0e, 0x11, 0x11, 0x0e, 0x11, 0x11, 0x0e}, /* 8 */
    {0x0e, 0x11, 0x11, 0x0f, 0x01, 0x02, 0x0c}, /* 9 */
    {0x00, 0x0c, 0x0c, 0x00, 0x0c, 0x0c, 0x00}, /* : */
    {0x00, 0x00, 0x1f, 0x00, 0x1f, 0x00, 0x00}, /* = */
    {0x0e, 0x11, 0x11, 0x1f, 0x11, 0x11, 0x11}, /* A */
    {0x1e, 0x11, 0x11, 0x1e, 0x11, 0x11, 0x1e}, /* B */
    {0x0e, 0x11, 0x10, 0x10, 0x10, 0x11, 0x0e}, /* C */
    {0x1c, 0x12, 0x11, 0x11, 0x11, 0x12, 0x1c}, /* D */
    {0x1f, 0x10, 0x10, 0x1e, 0x10, 0x10, 0x1f}, /* E */
    {0x1f, 0x10, 0x10, 0x1e, 0x10, 0x10, 0x10}, /* F */
    {0x0e, 0x11, 0x10, 0x17, 0x11, 0x11, 0x0f}, /* G */
    {0x11, 0x11, 0x11, 0x1f, 0x11, 0x11, 0x11}, /* H */
    {0x0e, 0x04, 0x04, 0x04, 0x04, 0x04, 0x0e}, /* I */
    {0x07, 0x02, 0x02, 0x02, 0x02, 0x12, 0x0c}, /* J */
    {0x11, 0x12, 0x14, 0x18, 0x14, 0x12, 0x11}, /* K */
    {0x10, 0x10, 0x10, 0x10, 0x10, 0x10, 0x1f}, /* L */
    {0x11, 0x1b, 0x15, 0x15, 0x11, 0x11, 0x11}, /* M */
    {0x11, 0x11, 0x19, 0x15, 0x13, 0x11, 0x11}, /* N */
    {0x0e, 0x11, 0x11, 0x11, 0x11, 0x11, 0x0e}, /* O */
    {0x1e, 0x11, 0x11, 0x1e, 0x10, 0x10, 0x10}, /* P */
    {0x0e, 0x11, 0x11, 0x11, 0x15, 0x12, 0x0d}, /* Q */
    {0x1e, 0x11, 0x11, 0x1e, 0x14, 0x12, 0x11}, /* R */
    {0x0f, 0x10, 0x10, 0x0e, 0x01, 0x01, 0x1e}, /* S */
    {0x1f, 0x04, 0x04, 0x04, 0x04, 0x04, 0x04}, /* T */
    {0x11, 0x11, 0x11, 0x11, 0x11, 0x11, 0x0e}, /* U */
    {0x11, 0x11, 0x11, 0x11, 0x11, 0x0a, 0x04}, /* V */
    {0x11, 0x11, 0x11, 0x15, 0x15, 0x15, 0x0a}, /* W */
    {0x11, 0x11, 0x0a, 0x04, 0x0a, 0x11, 0x11}, /* X */
    {0x11, 0x11, 0x11, 0x0a, 0x04, 0x04, 0x04}, /* Y */
    {0x1f, 0x01, 0x02, 0x04, 0x08, 0x10, 0x1f}, /* Z */
    {0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x1f}, /* _ */
};

const uint8_t *img_font_glyph(char c)
{
    if (c >= 'a' && c <= 'z') c = (char)(c - 'a' + 'A');
    for (int i = 0; font_chars[i]; i++)
        if (font_chars[i] == c) return font_rows[i];
    return NULL;
}

int img_text(img_t *im, int x, int y, const char *s, uint32_t rgba, int scale)
{
    for (; *s; s++) {
        const uint8_t *rows = img_font_glyph(*s);
        if (rows)
            for (int row = 0; row < 7; row++)
                for (int col = 0; col < 5; col++)
                    if (rows[row] & (0x10 >> col))
                        img_rect(im, x + col * scale, y + row * scale, x + (col + 1) * scale, y + (row + 1) * scale, rgba);
        x += 6 * scale;
    }
    return x;
}

bool png_write_rgb(const char *path, const uint8_t *rgb, int w, int h, int stride)
{
    FILE *f = fopen(path, "wb");
    if (!f) return false;
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    png_infop info = png ? png_create_info_struct(png) : NULL;
    if (!png || !info || setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        fclose(f);
        return false;
    }
    png_init_io(png, f);
    png_set_IHDR(png, info, (png_uint_32)w, (png_uint_32)h, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_set_compression_level(png, 9);
    png_write_info(png, info);
    for (int y = 0; y < h; y++) png_write_row(png, (png_const_bytep)(rgb + (size_t)y * (size_t)stride));
    png_write_end(png, NULL);
    png_destroy_write_struct(&png, &info);
    return fclose(f) == 0;
}

bool img_write_png(const img_t *im, const char *path)
{
    return png_write_rgb(path, im->rgb, im->w, im->h, im->w * 3);
}
