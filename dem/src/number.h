/* Reading a number without a floating-point trap.
 *
 * OpenFOAM enables traps on overflow, division by zero and invalid operations for the whole
 * process (FOAM_SIGFPE), and strtod of "1e400" overflows by definition: inside the solver a
 * number our reader would reject with its file, line and key killed the process instead. The
 * readers convert with the traps masked, clear the flags, restore the traps, and then check the
 * value (finite, in range) themselves before any arithmetic uses it. */
#ifndef DEM_NUMBER_H
#define DEM_NUMBER_H

/* strtod, with whatever floating-point traps are enabled masked during the conversion */
double dem_strtod(const char *text, char **end);

#endif
