#ifndef VCG_EXT_SNAKE_ERROR_H
#define VCG_EXT_SNAKE_ERROR_H

#include <stdexcept>
#include <string>

namespace vcg {
namespace tri {

/// The one exception type thrown at the vcg_ext boundary for bad input (empty mesh,
/// NaN coordinates, bad seeds, absurd parameters, ...). The message is written for the
/// user: the plugin shows it verbatim as the filter's error string or in the Log.
class SnakeError : public std::runtime_error
{
public:
    explicit SnakeError(const std::string &msg) : std::runtime_error(msg) {}
};

/// The user (through a progress callback) stopped a long computation.
class SnakeCancelled : public SnakeError
{
public:
    explicit SnakeCancelled(const std::string &msg) : SnakeError(msg) {}
};

} // namespace tri
} // namespace vcg

#endif
