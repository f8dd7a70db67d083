#pragma once

#include <stdexcept>
#include <string>

namespace devsurf::model {

// Thrown when an edit or a construction step would break the model; the message is a
// sentence that can be shown to the user as it is.
class ModelError : public std::runtime_error {
public:
    explicit ModelError(const std::string& message) : std::runtime_error(message) {}
};

} // namespace devsurf::model
