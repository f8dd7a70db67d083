#pragma once

// Helpers shared by the curve import tests.

#include "io/curves/curve_import.h"

#include <QFile>
#include <QString>

#include <cmath>
#include <random>
#include <string>

namespace devsurf::test {

inline std::string readBytes(const QString& path) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        return {};
    }
    const QByteArray data = file.readAll();
    return std::string(data.constData(), static_cast<std::size_t>(data.size()));
}

inline bool writeBytes(const QString& path, const std::string& bytes) {
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly)) {
        return false;
    }
    return file.write(bytes.data(), static_cast<qint64>(bytes.size())) ==
           static_cast<qint64>(bytes.size());
}

// A damaged copy: truncated, bits flipped, a number replaced by a hostile one, a span deleted
// or repeated, or random bytes.
inline std::string mutated(const std::string& good, std::mt19937& rng, int kind) {
    std::string bytes = good;
    switch (kind % 5) {
    case 0:
        return good.substr(0, rng() % good.size());
    case 1:
        for (int i = 0, flips = 1 + static_cast<int>(rng() % 4); i < flips; ++i) {
            bytes[rng() % bytes.size()] ^= static_cast<char>(1 << (rng() % 8));
        }
        return bytes;
    case 2: {
        // Numbers are where counts and sizes live.
        static const char* const hostile[] = {"0",          "-1",         "2147483647",  "1e308",
                                              "nan",        "99999999",   "-2147483648", "3",
                                              "4294967296", "1073741825", "inf",         "-0"};
        for (int tries = 0; tries < 50; ++tries) {
            const std::size_t at = rng() % bytes.size();
            if (std::isdigit(static_cast<unsigned char>(bytes[at]))) {
                std::size_t end = at;
                while (
                    end < bytes.size() &&
                    (std::isdigit(static_cast<unsigned char>(bytes[end])) || bytes[end] == '.')) {
                    ++end;
                }
                return bytes.substr(0, at) + hostile[rng() % std::size(hostile)] +
                       bytes.substr(end);
            }
        }
        return bytes;
    }
    case 3: {
        const std::size_t at = rng() % bytes.size();
        const std::size_t length = 1 + rng() % 64;
        if (rng() % 2 == 0) {
            bytes.erase(at, length);
        } else {
            bytes.insert(at, good.substr(at, length));
        }
        return bytes;
    }
    default: {
        std::string random(rng() % 2000, '\0');
        for (char& c : random) {
            c = static_cast<char>(rng() % 256);
        }
        return random;
    }
    }
}

} // namespace devsurf::test
