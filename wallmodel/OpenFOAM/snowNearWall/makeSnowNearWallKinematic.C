/* snowNearWall for basicKinematicCloud. */
#include "basicKinematicCloud.H"
#include "SnowNearWall.H"

makeCloudFunctionObjectType(SnowNearWall, basicKinematicCloud);
