/* swi_image.c - PNG (libpng simplified API) and JPEG (libjpeg) reading/writing. */
#include "swi_image.h"
#include "swi_error.h"
#include "swo_out.h"

#include <errno.h>
#include <stdio.h>      /* before jpeglib.h, which uses FILE */
#include <jpeglib.h>
#include <png.h>
#include <setjmp.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>


int swi_image_check_size(const char *name, const char *what, unsigned long width,
                          unsigned long height, char *err, size_t errlen)
{
    if (width >= 1 && height >= 1 && width <= SWI_IMAGE_MAX_SIDE && height <= SWI_IMAGE_MAX_SIDE &&
        width * height <= SWI_IMAGE_MAX_PIXELS)
        return 0;
    return swi_fail(err, errlen, 2,
                    "%s: %s header claims %lu x %lu pixels (%.1f MP); the limit is 1 .. %d px per "
                    "side and %g MP",
                    name, what, width, height, (double)width * (double)height / 1e6,
                    SWI_IMAGE_MAX_SIDE, SWI_IMAGE_MAX_PIXELS / 1e6);
}

swi_image *swi_image_alloc(int width, int height)
{
    if (width < 1 || height < 1 ||
        swi_image_check_size("", "", (unsigned long)width, (unsigned long)height, NULL, 0))
        return NULL;
    swi_image *img = malloc(sizeof *img);
    if (!img)
        return NULL;
    img->width = width;
    img->height = height;
    img->rgb = calloc((size_t)width * (size_t)height * 3u, 1);
    if (!img->rgb) {
        free(img);
        return NULL;
    }
    return img;
}

void swi_image_free(swi_image *img)
{
    if (!img)
        return;
    free(img->rgb);
    free(img);
}

/* PNG through libpng's simplified API: the header (IHDR) is read by begin_read and
 * its size checked before the pixel buffer exists. A truncated or corrupt stream
 * fails in finish_read (libpng reports it in pi.message, never on stderr).
 * Ancillary-chunk warnings (a bad sRGB profile, say) stay warnings. */
static int read_png(FILE *f, const char *name, swi_image **out, char *err, size_t errlen)
{
    png_image pi;
    memset(&pi, 0, sizeof pi);
    pi.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_stdio(&pi, f))
        return swi_fail(err, errlen, 2, "%s: not a readable PNG (%s)", name, pi.message);
    int rc = swi_image_check_size(name, "PNG", pi.width, pi.height, err, errlen);
    if (rc) {
        png_image_free(&pi);
        return rc;
    }
    pi.format = PNG_FORMAT_RGB;
    swi_image *img = swi_image_alloc((int)pi.width, (int)pi.height);
    if (!img) {
        png_image_free(&pi);
        return swi_fail(err, errlen, 1, "%s: out of memory for %ux%u pixels", name, pi.width,
                        pi.height);
    }
    if (!png_image_finish_read(&pi, NULL, img->rgb, 0, NULL)) {
        swi_image_free(img);
        return swi_fail(err, errlen, 2, "%s: PNG decoding failed (%s%s)", name, pi.message,
                        feof(f) ? ": the file ends early, truncated?" : "");
    }
    *out = img;
    return 0;
}

/* libjpeg error manager: errors AND warnings end the decoding through jb (a
 * warning is corrupt or missing data that libjpeg would otherwise paper over, e.g.
 * a truncated file decoded as grey); libjpeg never prints anything itself. */
struct jerr {
    struct jpeg_error_mgr pub;
    jmp_buf jb;
    char msg[JMSG_LENGTH_MAX];
};

static void jerr_exit(j_common_ptr cinfo)
{
    struct jerr *je = (struct jerr *)cinfo->err;
    (*cinfo->err->format_message)(cinfo, je->msg);
    longjmp(je->jb, 1);
}

static void jerr_emit(j_common_ptr cinfo, int msg_level)
{
    if (msg_level < 0)          /* a warning: corrupt data */
        jerr_exit(cinfo);
    /* trace messages (msg_level >= 0): ignored */
}

static void jerr_output(j_common_ptr cinfo)
{
    (void)cinfo;                /* never write to stderr */
}

static void jerr_init(struct jpeg_error_mgr *pub)
{
    jpeg_std_error(pub);
    pub->error_exit = jerr_exit;
    pub->emit_message = jerr_emit;
    pub->output_message = jerr_output;
}

/* A progressive JPEG may hold any number of scans, and the decoder passes over
 * the image's coefficients for each: a small file of many near-empty scans of a
 * large image costs scans x pixels. Photos have about 10 scans; more than
 * SWI_JPEG_MAX_SCANS is an error (libjpeg-turbo's own fuzzers use a limit too). */
struct jprog {
    struct jpeg_progress_mgr pub;
    struct jerr *je;
};

static void jprog_monitor(j_common_ptr cinfo)
{
    struct jprog *p = (struct jprog *)cinfo->progress;
    if (cinfo->is_decompressor &&
        ((j_decompress_ptr)cinfo)->input_scan_number > SWI_JPEG_MAX_SCANS) {
        snprintf(p->je->msg, sizeof p->je->msg, "more than %d scans", SWI_JPEG_MAX_SCANS);
        longjmp(p->je->jb, 1);
    }
}

static int read_jpeg(FILE *f, const char *name, swi_image **out, char *err, size_t errlen)
{
    struct jpeg_decompress_struct ci;
    struct jerr je;
    struct jprog prog;
    swi_image *volatile img = NULL;
    ci.err = &je.pub;
    jerr_init(&je.pub);
    if (setjmp(je.jb)) {
        jpeg_destroy_decompress(&ci);
        swi_image_free(img);
        return swi_fail(err, errlen, 2, "%s: JPEG decoding failed (%s)", name, je.msg);
    }
    jpeg_create_decompress(&ci);
    prog.pub.progress_monitor = jprog_monitor;
    prog.je = &je;
    ci.progress = &prog.pub;
    jpeg_stdio_src(&ci, f);
    jpeg_read_header(&ci, TRUE);
    /* the size from the frame header, before libjpeg or we allocate anything for it */
    int rc = swi_image_check_size(name, "JPEG", ci.image_width, ci.image_height, err, errlen);
    if (rc) {
        jpeg_destroy_decompress(&ci);
        return rc;
    }
    ci.out_color_space = JCS_RGB;
    jpeg_start_decompress(&ci);
    if (ci.output_components != 3) {
        jpeg_destroy_decompress(&ci);
        return swi_fail(err, errlen, 2, "%s: JPEG with %d components, expected RGB", name,
                        ci.output_components);
    }
    img = swi_image_alloc((int)ci.output_width, (int)ci.output_height);
    if (!img) {
        jpeg_destroy_decompress(&ci);
        return swi_fail(err, errlen, 1, "%s: out of memory for %ux%u pixels", name,
                        ci.output_width, ci.output_height);
    }
    while (ci.output_scanline < ci.output_height) {
        JSAMPROW row = img->rgb + (size_t)ci.output_scanline * (size_t)img->width * 3u;
        jpeg_read_scanlines(&ci, &row, 1);
    }
    jpeg_finish_decompress(&ci);
    jpeg_destroy_decompress(&ci);
    *out = img;
    return 0;
}

/* The one decoding path: a PNG or JPEG from an open stream, detected from its
 * first bytes. */
static int read_stream(FILE *f, const char *name, swi_image **out, char *err, size_t errlen)
{
    unsigned char magic[8] = {0};
    size_t n = fread(magic, 1, sizeof magic, f);
    if (ferror(f) || fseek(f, 0, SEEK_SET) != 0)
        return swi_fail(err, errlen, 2, "%s: cannot read (%s)", name, strerror(errno));
    static const unsigned char png_sig[8] = {0x89, 'P', 'N', 'G', 0x0d, 0x0a, 0x1a, 0x0a};
    if (n == 8 && memcmp(magic, png_sig, 8) == 0)
        return read_png(f, name, out, err, errlen);
    if (n >= 3 && magic[0] == 0xff && magic[1] == 0xd8 && magic[2] == 0xff)
        return read_jpeg(f, name, out, err, errlen);
    if (n == 0)
        return swi_fail(err, errlen, 2, "%s: empty file (neither PNG nor JPEG)", name);
    return swi_fail(err, errlen, 2, "%s: neither PNG nor JPEG (unknown file signature)", name);
}

int swi_image_read(const char *path, swi_image **out, char *err, size_t errlen)
{
    *out = NULL;
    FILE *f = fopen(path, "rb");
    if (!f)
        return swi_fail(err, errlen, 2, "%s: cannot open (%s)", path, strerror(errno));
    int rc = read_stream(f, path, out, err, errlen);
    fclose(f);
    return rc;
}

int swi_image_read_mem(const unsigned char *data, size_t n, const char *name, swi_image **out,
                       char *err, size_t errlen)
{
    *out = NULL;
    if (!name)
        name = "(memory)";
    if (!data || n == 0)
        return swi_fail(err, errlen, 2, "%s: empty file (neither PNG nor JPEG)", name);
    /* read-only use of data: fmemopen's buffer is not const in its prototype */
    FILE *f = fmemopen((void *)(uintptr_t)data, n, "rb");
    if (!f)
        return swi_fail(err, errlen, 1, "%s: fmemopen failed (%s)", name, strerror(errno));
    int rc = read_stream(f, name, out, err, errlen);
    fclose(f);
    return rc;
}

/* The writers go through the common output writer (swo_out.h): a temporary
 * in path's folder, every write error checked, renamed over path only when
 * path is absent or a regular file (a device, FIFO, folder or link there is
 * refused, code 2, and left as it is); on failure the temporary is removed. */
static FILE *open_out(const char *path, swo_set **set, int *code, char *err, size_t errlen)
{
    char e[600];
    *set = NULL;
    const swo_spec spec = { "snowphoto", "--out", NULL, 0, 0 };
    int rc = swo_alloc(&spec, set, e, sizeof e);
    FILE *f = rc == SWO_OK ? swo_open(*set, path, e, sizeof e) : NULL;
    if (!f) {
        *code = swi_fail(err, errlen, *set ? swo_code(*set) : rc, "%s", e);
        swo_free(*set);
        *set = NULL;
    }
    return f;
}

static int finish_out(swo_set *set, char *err, size_t errlen)
{
    char e[600];
    int rc = swo_commit(set, e, sizeof e);
    if (rc != SWO_OK)
        swi_fail(err, errlen, rc, "%s", e);
    swo_free(set);
    return rc;
}

/* an encoder failed: the set is dropped, its temporary removed */
static int drop_out(swo_set *set)
{
    swo_free(set);
    return 1;
}

int swi_image_write_png(const char *path, const swi_image *img, char *err, size_t errlen)
{
    swo_set *set;
    int code;
    FILE *f = open_out(path, &set, &code, err, errlen);
    if (!f)
        return code;
    png_image pi;
    memset(&pi, 0, sizeof pi);
    pi.version = PNG_IMAGE_VERSION;
    pi.width = (png_uint_32)img->width;
    pi.height = (png_uint_32)img->height;
    pi.format = PNG_FORMAT_RGB;
    if (!png_image_write_to_stdio(&pi, f, 0, img->rgb, 0, NULL)) {
        drop_out(set);
        return swi_fail(err, errlen, 1, "%s: PNG encoding failed (%s)", path, pi.message);
    }
    return finish_out(set, err, errlen);
}

int swi_image_write_jpeg(const char *path, const swi_image *img, int quality, char *err,
                         size_t errlen)
{
    if (quality < 1 || quality > 100)
        return swi_fail(err, errlen, 2, "JPEG quality %d outside 1..100", quality);
    swo_set *set;
    int code;
    FILE *f = open_out(path, &set, &code, err, errlen);
    if (!f)
        return code;
    struct jpeg_compress_struct ci;
    struct jerr je;
    ci.err = &je.pub;
    jerr_init(&je.pub);
    if (setjmp(je.jb)) {
        jpeg_destroy_compress(&ci);
        drop_out(set);
        return swi_fail(err, errlen, 1, "%s: JPEG encoding failed (%s)", path, je.msg);
    }
    jpeg_create_compress(&ci);
    jpeg_stdio_dest(&ci, f);
    ci.image_width = (JDIMENSION)img->width;
    ci.image_height = (JDIMENSION)img->height;
    ci.input_components = 3;
    ci.in_color_space = JCS_RGB;
    jpeg_set_defaults(&ci);
    jpeg_set_quality(&ci, quality, TRUE);
    jpeg_start_compress(&ci, TRUE);
    while (ci.next_scanline < ci.image_height) {
        JSAMPROW row = img->rgb + (size_t)ci.next_scanline * (size_t)img->width * 3u;
        jpeg_write_scanlines(&ci, &row, 1);
    }
    jpeg_finish_compress(&ci);
    jpeg_destroy_compress(&ci);
    return finish_out(set, err, errlen);
}

static double luma_px(const swi_image *img, int x, int y)
{
    const unsigned char *p = img->rgb + ((size_t)y * (size_t)img->width + (size_t)x) * 3u;
    return (0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2]) / 255.0;
}

double swi_image_luma(const swi_image *img, double x, double y)
{
    /* pixel i covers [i, i+1): centre at i + 0.5 */
    double fx = x - 0.5, fy = y - 0.5;
    if (!(fx > 0)) fx = 0;
    if (!(fy > 0)) fy = 0;
    if (fx > img->width - 1) fx = img->width - 1;
    if (fy > img->height - 1) fy = img->height - 1;
    int x0 = (int)fx, y0 = (int)fy;
    int x1 = x0 + 1 < img->width ? x0 + 1 : x0;
    int y1 = y0 + 1 < img->height ? y0 + 1 : y0;
    double ax = fx - x0, ay = fy - y0;
    return (1 - ay) * ((1 - ax) * luma_px(img, x0, y0) + ax * luma_px(img, x1, y0)) +
           ay * ((1 - ax) * luma_px(img, x0, y1) + ax * luma_px(img, x1, y1));
}
