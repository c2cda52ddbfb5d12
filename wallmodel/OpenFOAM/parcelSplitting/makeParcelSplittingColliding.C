/* parcelSplitting for basicKinematicCollidingCloud
   (icoUncoupledKinematicParcelFoam, DPMFoam). */
#include "basicKinematicCollidingCloud.H"
#include "ParcelSplitting.H"

makeCloudFunctionObjectType(ParcelSplitting, basicKinematicCollidingCloud);
