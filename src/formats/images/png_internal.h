/* Private libpng glue shared by the PNG reader and writer (not installed). */
#ifndef SK_IO_PNG_INTERNAL_H
#define SK_IO_PNG_INTERNAL_H

#include <png.h>

/* libpng reports errors through a callback that must not return: the callback stores
 * libpng's message here (the struct is the png "error pointer") and long-jumps back to
 * the setjmp in the function that drives libpng. */
typedef struct sk__png_error {
    char message[192];
} sk__png_error;

void sk__png_on_error(png_structp png, png_const_charp message);
/* Warnings (e.g. a bad CRC on an ancillary chunk, which libpng then skips) are not
 * printed: a library does not write to stderr. */
void sk__png_on_warning(png_structp png, png_const_charp message);

/* libpng's own allocations (row buffers, zlib state, chunk data) go through these. A
 * corrupt chunk length makes libpng 1.6 allocate the claimed size before it reads a byte;
 * refusing single allocations above SK__PNG_MAX_ALLOCATION turns that into an error
 * instead of gigabytes of memory. libpng never allocates the whole image. */
#define SK__PNG_MAX_ALLOCATION ((png_alloc_size_t)16 << 20)
png_voidp sk__png_malloc(png_structp png, png_alloc_size_t size);
void sk__png_free(png_structp png, png_voidp ptr);

#endif
