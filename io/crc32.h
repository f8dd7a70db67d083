#pragma once

#include <boost/crc.hpp>

#include <cstddef>
#include <cstdint>

namespace devsurf::io {

// The CRC-32 of zlib, PNG and ZIP (reflected polynomial 0xEDB88320) that the project file's
// envelope carries, by Boost.CRC.
inline std::uint32_t crc32(const void* data, std::size_t size) {
    boost::crc_32_type crc;
    crc.process_bytes(data, size);
    return crc.checksum();
}

} // namespace devsurf::io
