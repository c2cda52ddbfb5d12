/* parcelSplitting for basicReactingMultiphaseCloud (reactingParcelFoam, simpleReactingParcelFoam; coalChemistryFoam's coalCloud shares the parcel type). */
#include "basicReactingMultiphaseCloud.H"
#include "ParcelSplitting.H"

makeCloudFunctionObjectType(ParcelSplitting, basicReactingMultiphaseCloud);
