#ifndef slSMPFor_h
#define slSMPFor_h
/**
 * @file slSMPFor.h
 * @brief vtkSMPTools::For with its threads kept on different CPUs.
 *
 * The parallel loops of ShadeLab's normals filters and of the checks they
 * run first go through slSMPFor: a thread-pool worker that the loop wakes
 * on the CPU of the thread that started it moves to another CPU before its
 * first chunk (shadelab/ThreadSpread.h), instead of waiting there for that
 * thread's time slice. Nothing else changes: the same chunks, the same
 * grain, the same backend. C++ only (not wrapped).
 */

#include "shadelab/ThreadSpread.h"

#include <vtkSMPTools.h>

/// Calls @p body(b, e) on sub-ranges of [@p begin, @p end), as
/// vtkSMPTools::For(begin, end, grain, body) does.
template <typename Body>
void slSMPFor(vtkIdType begin, vtkIdType end, vtkIdType grain, Body&& body)
{
  shadelab::ThreadSpread spread;
  vtkSMPTools::For(begin, end, grain, [&spread, &body](vtkIdType b, vtkIdType e) {
    spread.enter();
    body(b, e);
  });
}

#endif
