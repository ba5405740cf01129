/* Angle wrapping and bearings, the same operations in the same order as mcl/Angles.java. */
#include <math.h>

#include "angles.h"

double jm_wrap2pi(double a)
{
	double r = a - JM_TWO_PI * floor(a / JM_TWO_PI);

	return r >= JM_TWO_PI ? 0.0 : r;
}

double jm_wrappi(double a)
{
	return jm_wrap2pi(a + JM_PI) - JM_PI;
}

double jm_bearing(double px, double py, double pth, double bx, double by)
{
	return jm_wrap2pi(atan2(by - py, bx - px) - pth);
}
