/* fuzz_image.c - libFuzzer target: snowphoto's photo readers (PNG and JPEG,
 * told apart by their bytes; swi_image_read_mem, tools/snowphoto/swi_image.c).
 *
 * Any bytes as a photo: 0 with an image whose size and pixels are readable,
 * or 1/2 with one line in err (no crash, no sanitizer report, no hang, no
 * allocation beyond the size limit). The decoders are Debian's libpng and
 * libjpeg (not instrumented: the coverage counts SnowWall's own code). */
#include <stdint.h>
#include <string.h>

#include "swi_image.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    swi_image *img = NULL;
    char err[300];
    const int rc = swi_image_read_mem(data, size, "fuzz", &img, err, sizeof err);
    if (rc != 0) {
        if (img || !err[0] || strchr(err, '\n'))
            __builtin_trap(); /* no image, one line */
        return 0;
    }
    if (!img || img->width < 1 || img->height < 1 || !img->rgb)
        __builtin_trap();
    /* touch the first and last pixel: the buffer holds width x height x 3 */
    volatile unsigned char s = img->rgb[0];
    s = img->rgb[(size_t)img->width * (size_t)img->height * 3 - 1];
    (void)s;
    swi_image_free(img);
    return 0;
}
