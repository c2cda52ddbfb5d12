/* wellMixedCheck for basicKinematicCloud. */
#include "basicKinematicCloud.H"
#include "WellMixedCheck.H"

makeCloudFunctionObjectType(WellMixedCheck, basicKinematicCloud);
