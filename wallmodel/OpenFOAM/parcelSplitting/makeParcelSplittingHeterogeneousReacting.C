/* parcelSplitting for basicHeterogeneousReactingCloud (reactingHeterogenousParcelFoam). */
#include "basicHeterogeneousReactingCloud.H"
#include "ParcelSplitting.H"

makeCloudFunctionObjectType(ParcelSplitting, basicHeterogeneousReactingCloud);
