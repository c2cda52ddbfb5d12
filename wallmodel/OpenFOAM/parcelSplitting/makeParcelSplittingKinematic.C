/* parcelSplitting for basicKinematicCloud (uncoupledKinematicParcelFoam,
   pimpleUncoupledKinematicParcelFoam). */
#include "basicKinematicCloud.H"
#include "ParcelSplitting.H"

makeCloudFunctionObjectType(ParcelSplitting, basicKinematicCloud);
