/* swi_testimg - write a synthetic rear-face photo and simulated map for the
 * snowphoto command tests, or a hostile image.
 * Usage: swi_testimg PHOTO.(png|jpg) SIM.csv
 *        swi_testimg --png-claiming W H OUT.png     a real 1x1 PNG whose header says W x H
 *        swi_testimg --jpeg-claiming W H OUT.jpg    a real 96x96 noise JPEG (about 12 KB)
 *                                                   whose header says W x H
 * Photo: snow on the top-left quadrant of the face (u < 0.5, v < 0.5), face corners
 * 100,80,540,60,580,420,60,400 in a 640x480 image. Map: 8x8 faces, snow where
 * u < 0.75 and v < 0.5. Expected: IoU 2/3, Dice 0.8, precision 2/3, recall 1. */
#include <string.h>
#include "swi_synth.h"

int main(int argc, char **argv)
{
    if (argc == 5 && (!strcmp(argv[1], "--png-claiming") || !strcmp(argv[1], "--jpeg-claiming"))) {
        unsigned long w = strtoul(argv[2], NULL, 10), h = strtoul(argv[3], NULL, 10);
        int rc = argv[1][2] == 'p' ? synth_png_claiming(argv[4], w, h)
                                   : synth_jpeg_claiming(argv[4], 96, 96, w, h);
        if (rc)
            fprintf(stderr, "swi_testimg: cannot write %s\n", argv[4]);
        return rc;
    }
    if (argc != 3) {
        fprintf(stderr, "usage: swi_testimg PHOTO.(png|jpg) SIM.csv\n"
                        "       swi_testimg --png-claiming|--jpeg-claiming W H OUT\n");
        return 2;
    }
    swi_image *img = synth_photo(0.5, 0.5);
    if (!img)
        return 1;
    char err[512];
    size_t n = strlen(argv[1]);
    int jpg = n > 4 && (!strcmp(argv[1] + n - 4, ".jpg") || !strcmp(argv[1] + n - 4, ".JPG"));
    int rc = jpg ? swi_image_write_jpeg(argv[1], img, 95, err, sizeof err)
                 : swi_image_write_png(argv[1], img, err, sizeof err);
    swi_image_free(img);
    if (rc) {
        fprintf(stderr, "swi_testimg: %s\n", err);
        return 1;
    }
    return synth_csv(argv[2], 8, 0.0, 0.75, 0.5);
}
