/* snowWallInteraction for basicHeterogeneousReactingCloud (reactingHeterogenousParcelFoam). */
#include "basicHeterogeneousReactingCloud.H"
#include "SnowWallInteraction.H"

makePatchInteractionModelType(SnowWallInteraction, basicHeterogeneousReactingCloud);
