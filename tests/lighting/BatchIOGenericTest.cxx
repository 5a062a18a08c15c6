// BatchIOTest.cxx compiled without the radiance loop's AVX options: the
// lane-by-lane path of slBatchIO.h that machines without AVX use (on
// ShadeLab's machines the loop itself takes the AVX path).
#ifdef __AVX__
#error "BatchIOGenericTest.cxx must be compiled without AVX"
#endif
#include "BatchIOTest.cxx"
