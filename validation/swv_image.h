/* swv_image.h - RGB images for the photo comparison: read PNG/JPEG, write PNG/JPEG.
 *
 * Lifecycle: swv_image_alloc / swv_image_read -> use -> swv_image_free.
 * Every function returns 0 on success and a non-zero code with a one-line
 * message in err (err may be NULL) on failure; nothing exits. Writers write a
 * temporary file in the destination folder and rename() it into place.
 */
#ifndef SWV_IMAGE_H
#define SWV_IMAGE_H
#include <stddef.h>

typedef struct swv_image {
    int width, height;          /* pixels */
    unsigned char *rgb;         /* width*height*3 bytes, row-major, top row first */
} swv_image;

/* New black image (width, height >= 1). NULL on bad size or no memory. */
swv_image *swv_image_alloc(int width, int height);
void swv_image_free(swv_image *img);

/* Read a PNG or JPEG (detected from the file's first bytes) as 8-bit RGB. */
int swv_image_read(const char *path, swv_image **out, char *err, size_t errlen);

int swv_image_write_png(const char *path, const swv_image *img, char *err, size_t errlen);
/* quality 1..100 */
int swv_image_write_jpeg(const char *path, const swv_image *img, int quality,
                         char *err, size_t errlen);

/* Luminance in [0, 1] (Rec. 601 weights) of pixel (x, y), bilinear between pixel
 * centres at non-integer positions; positions are clamped to the image. */
double swv_image_luma(const swv_image *img, double x, double y);

#endif
