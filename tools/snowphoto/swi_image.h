/* swi_image.h - RGB images for the photo comparison: read PNG/JPEG, write PNG/JPEG.
 *
 * Lifecycle: swi_image_alloc / swi_image_read -> use -> swi_image_free.
 * Every function returns 0 on success and a non-zero code with a one-line
 * message in err (err may be NULL) on failure; nothing exits. Writers go
 * through the common output writer (common/swo_out.h): a temporary in the
 * destination folder renamed into place once whole; code 2 when the path is
 * refused (its folder missing or unwritable; a folder, device, FIFO, socket or
 * link at the path, left as it is), 1 on a write failure (a full disk).
 */
#ifndef SWI_IMAGE_H
#define SWI_IMAGE_H
#include <stddef.h>

typedef struct swi_image {
    int width, height;          /* pixels */
    unsigned char *rgb;         /* width*height*3 bytes, row-major, top row first */
} swi_image;

/* Size limits, checked from the file's header before any pixel memory exists
 * (a 12 KB file may claim 60000 x 60000 pixels = 10.8 GB): at most
 * SWI_IMAGE_MAX_SIDE pixels per side and SWI_IMAGE_MAX_PIXELS in all (100 MP,
 * 300 MB as 8-bit RGB). A progressive JPEG may have at most SWI_JPEG_MAX_SCANS
 * scans (photos have about 10; thousands of empty scans are a time bomb). */
#ifndef SWI_IMAGE_MAX_SIDE          /* a fuzzing build may define smaller limits */
#define SWI_IMAGE_MAX_SIDE 30000
#endif
#ifndef SWI_IMAGE_MAX_PIXELS
#define SWI_IMAGE_MAX_PIXELS 100000000
#endif
#ifndef SWI_JPEG_MAX_SCANS
#define SWI_JPEG_MAX_SCANS 1000
#endif

/* 0 when width x height is within the limits, else 2 and "NAME: WHAT header
 * claims W x H pixels (... MP); the limit is ..." in err. */
int swi_image_check_size(const char *name, const char *what, unsigned long width,
                         unsigned long height, char *err, size_t errlen);

/* New black image (width, height >= 1, within the size limits). NULL on bad size
 * or no memory. */
swi_image *swi_image_alloc(int width, int height);
void swi_image_free(swi_image *img);

/* Read a PNG or JPEG (detected from the file's first bytes) as 8-bit RGB.
 * Checks, in this order, with code 2 and a message naming the file: the
 * signature; the header's size against the limits above (before decoding);
 * then every libpng error and every libjpeg error AND warning (corrupt or
 * truncated data: libjpeg would otherwise fill the missing part with grey and
 * succeed). Nothing is printed by the libraries. Code 1: out of memory. */
int swi_image_read(const char *path, swi_image **out, char *err, size_t errlen);

/* The same reader on bytes in memory (data[0..n), not modified; name is used in
 * messages, NULL gives "(memory)"): the entry point for fuzzing. *out is NULL
 * unless 0 is returned. */
int swi_image_read_mem(const unsigned char *data, size_t n, const char *name, swi_image **out,
                       char *err, size_t errlen);

int swi_image_write_png(const char *path, const swi_image *img, char *err, size_t errlen);
/* quality 1..100 */
int swi_image_write_jpeg(const char *path, const swi_image *img, int quality,
                         char *err, size_t errlen);

/* Luminance in [0, 1] (Rec. 601 weights) of pixel (x, y), bilinear between pixel
 * centres at non-integer positions; positions are clamped to the image. */
double swi_image_luma(const swi_image *img, double x, double y);

#endif
