/* snowWallInteraction for basicReactingMultiphaseCloud (reactingParcelFoam, simpleReactingParcelFoam; also
   coalChemistryFoam's coalCloud, whose parcel type is the same, so it shares
   this registration). */
#include "basicReactingMultiphaseCloud.H"
#include "SnowWallInteraction.H"

makePatchInteractionModelType(SnowWallInteraction, basicReactingMultiphaseCloud);
