/* wellMixedCheck for basicKinematicCollidingCloud. */
#include "basicKinematicCollidingCloud.H"
#include "WellMixedCheck.H"

makeCloudFunctionObjectType(WellMixedCheck, basicKinematicCollidingCloud);
