/* parcelSplitting for basicKinematicMPPICCloud (MPPICFoam). */
#include "basicKinematicMPPICCloud.H"
#include "ParcelSplitting.H"

makeCloudFunctionObjectType(ParcelSplitting, basicKinematicMPPICCloud);
