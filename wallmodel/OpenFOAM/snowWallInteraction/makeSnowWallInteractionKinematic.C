/* snowWallInteraction for basicKinematicCloud (uncoupledKinematicParcelFoam). */
#include "basicKinematicCloud.H"
#include "SnowWallInteraction.H"

makePatchInteractionModelType(SnowWallInteraction, basicKinematicCloud);
