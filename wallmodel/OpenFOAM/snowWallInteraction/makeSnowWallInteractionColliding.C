/* snowWallInteraction for basicKinematicCollidingCloud (icoUncoupledKinematicParcelFoam). */
#include "basicKinematicCollidingCloud.H"
#include "SnowWallInteraction.H"

makePatchInteractionModelType(SnowWallInteraction, basicKinematicCollidingCloud);
