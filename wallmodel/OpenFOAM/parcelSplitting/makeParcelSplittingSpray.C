/* parcelSplitting for basicSprayCloud (sprayFoam, engineFoam). */
#include "basicSprayCloud.H"
#include "ParcelSplitting.H"

makeCloudFunctionObjectType(ParcelSplitting, basicSprayCloud);
