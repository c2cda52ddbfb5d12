/* sbd_stl.h - a surface as ASCII STL, one solid per region (named by
 * sbd_region_name), which OpenFOAM's triSurface reads as its regions. */
#ifndef SBD_STL_H
#define SBD_STL_H

#include "sbd_body.h"
#include <stdio.h>

/* 0, or -1 with a message when the stream fails */
int sbd_stl_write(const sbd_surface *s, FILE *f, char *err, size_t errlen);

#endif
