/* snowNearWall for basicKinematicCollidingCloud. */
#include "basicKinematicCollidingCloud.H"
#include "SnowNearWall.H"

makeCloudFunctionObjectType(SnowNearWall, basicKinematicCollidingCloud);
