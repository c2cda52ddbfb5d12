/* snowWallInteraction for basicSprayCloud (sprayFoam, engineFoam). */
#include "basicSprayCloud.H"
#include "SnowWallInteraction.H"

makePatchInteractionModelType(SnowWallInteraction, basicSprayCloud);
