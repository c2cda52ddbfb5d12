/* snowWallInteraction for basicKinematicMPPICCloud (MPPICFoam). */
#include "basicKinematicMPPICCloud.H"
#include "SnowWallInteraction.H"

makePatchInteractionModelType(SnowWallInteraction, basicKinematicMPPICCloud);
