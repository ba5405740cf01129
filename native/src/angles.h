/* Angle arithmetic of docs/ALGORITHM.md section 3: headings in [0, 2pi), differences in [-pi, pi). */
#ifndef JM_ANGLES_H
#define JM_ANGLES_H

/* 2pi, the literal both languages use (Java 2 * Math.PI). */
#define JM_TWO_PI 6.283185307179586
#define JM_PI 3.141592653589793

/* The angle wrapped to [0, 2pi). */
double jm_wrap2pi(double a);
/* The angle wrapped to [-pi, pi). */
double jm_wrappi(double a);
/* The angle at which a robot at (px, py) heading pth sees the point (bx, by), in [0, 2pi). */
double jm_bearing(double px, double py, double pth, double bx, double by);

#endif
