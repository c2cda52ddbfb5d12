/* snowWallInteraction for basicThermoCloud (the limestone cloud of coalChemistryFoam). */
#include "basicThermoCloud.H"
#include "SnowWallInteraction.H"

makePatchInteractionModelType(SnowWallInteraction, basicThermoCloud);
