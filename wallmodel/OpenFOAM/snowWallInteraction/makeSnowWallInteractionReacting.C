/* snowWallInteraction for basicReactingCloud (fireFoam). */
#include "basicReactingCloud.H"
#include "SnowWallInteraction.H"

makePatchInteractionModelType(SnowWallInteraction, basicReactingCloud);
