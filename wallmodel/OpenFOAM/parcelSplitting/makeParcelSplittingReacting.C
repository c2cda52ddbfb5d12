/* parcelSplitting for basicReactingCloud (fireFoam). */
#include "basicReactingCloud.H"
#include "ParcelSplitting.H"

makeCloudFunctionObjectType(ParcelSplitting, basicReactingCloud);
