/* parcelSplitting for basicThermoCloud (the limestone cloud of coalChemistryFoam). */
#include "basicThermoCloud.H"
#include "ParcelSplitting.H"

makeCloudFunctionObjectType(ParcelSplitting, basicThermoCloud);
