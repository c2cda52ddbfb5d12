/* The box of tests/openfoam/box in Code_Saturne: boundary zones by position
 * (0.1 m cube; wall y = 0, top y = 0.1, sides the rest), and one volume zone
 * p1 .. p7 per particle: the cell (0.025 m cube) that holds its start point,
 * in which it is injected on whichever MPI rank has that cell. */
#include "cs_defs.h"
#include <stdio.h>

#include "cs_boundary_zone.h"
#include "cs_volume_zone.h"
#include "cs_prototypes.h"

BEGIN_C_DECLS

void
cs_user_zones(void)
{
  cs_boundary_zone_define("wall", "y < 1e-6", 0);
  cs_boundary_zone_define("top", "y > 0.099999", 0);
  cs_boundary_zone_define("sides", "x < 1e-6 or x > 0.099999 or z < 1e-6 or z > 0.099999", 0);
  /* the cells of p1 .. p7 (cs_user_lagr_particle.c), by their centres. p6
     starts on the face z = 0.05 between two cells: Code_Saturne 6.0 tracks it
     right from the cell below (z < 0.05); from the one above, the tracking
     moves its start (measured: its impact 0.5 mm off) */
  static const char *const cells[7] = {
    "box[0.0, 0.05, 0.0, 0.025, 0.075, 0.025]", "box[0.05, 0.05, 0.0, 0.075, 0.075, 0.025]",
    "box[0.075, 0.05, 0.0, 0.1, 0.075, 0.025]", "box[0.0, 0.0, 0.075, 0.025, 0.025, 0.1]",
    "box[0.05, 0.0, 0.075, 0.075, 0.025, 0.1]", "box[0.025, 0.0, 0.025, 0.05, 0.025, 0.05]",
    "box[0.075, 0.0, 0.075, 0.1, 0.025, 0.1]"};
  for (int i = 0; i < 7; i++) {
    char name[8];
    snprintf(name, sizeof name, "p%d", i + 1);
    cs_volume_zone_define(name, cells[i], 0);
  }
}

END_C_DECLS
