/**
 * @file demo_raster.h
 * @brief Tiny RGB rasterizer for the example's pictures (host only): alpha-blended lines,
 *        filled triangles, discs, a 5x7 bitmap font, and a PNG writer on libpng.
 */
#ifndef CHAR_BODY_EXAMPLE_DEMO_RASTER_H
#define CHAR_BODY_EXAMPLE_DEMO_RASTER_H

#include <stdbool.h>
#include <stdint.h>

typedef struct {
    int w, h;
    uint8_t *rgb; ///< w * h * 3 bytes, rows top to bottom
} img_t;

/** Colours are 0xRRGGBBAA (the char_body debug-draw format). */
bool img_init(img_t *im, int w, int h, uint32_t rgba);
void img_free(img_t *im);
void img_blend(img_t *im, int x, int y, uint32_t rgba, float cover);
/** Anti-aliased line of the given width in pixels (sub-pixel end points). */
void img_line(img_t *im, float x0, float y0, float x1, float y1, uint32_t rgba, float width);
/** Filled triangle (no anti-aliasing), alpha-blended. */
void img_tri(img_t *im, float x0, float y0, float x1, float y1, float x2, float y2, uint32_t rgba);
void img_disc(img_t *im, float cx, float cy, float r, uint32_t rgba);
void img_rect(img_t *im, int x0, int y0, int x1, int y1, uint32_t rgba);
/** Text with the built-in 5x7 font; scale = pixels per font dot. Returns the end x. */
int img_text(img_t *im, int x, int y, const char *s, uint32_t rgba, int scale);
/** The 5x7 glyph of c (7 rows, bit 4 = leftmost dot), or NULL; letters are upper case. */
const uint8_t *img_font_glyph(char c);
/** 8-bit RGB PNG. */
bool img_write_png(const img_t *im, const char *path);
/** Writes rows of RGB pixels (stride in bytes) as PNG; used by the SDL screenshot too. */
bool png_write_rgb(const char *path, const uint8_t *rgb, int w, int h, int stride);

#endif
