#ifndef shadelab_app_Counted_h
#define shadelab_app_Counted_h
/**
 * @file Counted.h
 * @brief "1 point", "3 points": a count and its noun, for the lines the
 * subcommands print about what they wrote.
 */

#include <string>

namespace shadelab
{
namespace app
{

/// @p n followed by @p noun, with an "s" unless @p n is 1.
inline std::string counted(long long n, const std::string& noun)
{
  return std::to_string(n) + " " + noun + (n == 1 ? "" : "s");
}

} // namespace app
} // namespace shadelab

#endif
