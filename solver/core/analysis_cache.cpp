#include "solver/core/analysis_cache.h"

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <cstring>
#include <list>
#include <mutex>

namespace devsurf::solver {

namespace {

std::atomic<long long> g_symbolicAnalyses{0};

constexpr std::uint64_t kFnvOffset = 1469598103934665603ull;
constexpr std::uint64_t kFnvPrime = 1099511628211ull;

void mix(std::uint64_t& hash, std::uint64_t value) {
    for (int byte = 0; byte < 8; ++byte) {
        hash ^= (value >> (8 * byte)) & 0xffu;
        hash *= kFnvPrime;
    }
}

} // namespace

std::uint64_t patternHash(int variables, const std::vector<int>& colStart,
                          const std::vector<int>& rowIndex, FactorizationMethod method) {
    std::uint64_t hash = kFnvOffset;
    mix(hash, static_cast<std::uint64_t>(variables));
    mix(hash, static_cast<std::uint64_t>(colStart.size()));
    mix(hash, static_cast<std::uint64_t>(rowIndex.size()));
    mix(hash, static_cast<std::uint64_t>(method));
    for (int value : colStart) {
        mix(hash, static_cast<std::uint32_t>(value));
    }
    for (int value : rowIndex) {
        mix(hash, static_cast<std::uint32_t>(value));
    }
    return hash;
}

long long symbolicAnalysisCount() {
    return g_symbolicAnalyses.load();
}

void countSymbolicAnalysis() {
    ++g_symbolicAnalyses;
}

struct AnalysisCache::Impl {
    mutable std::mutex mutex;
    // Most recently used first.
    std::list<std::shared_ptr<const CachedAnalysis>> entries;
    std::size_t capacity = 16;
    long long hits = 0;
    bool enabled = true;

    void trim() {
        while (entries.size() > capacity) {
            entries.pop_back();
        }
    }
};

AnalysisCache::AnalysisCache() : m_impl(std::make_unique<Impl>()) {
    // DEVSURF_ANALYSIS_CACHE=0 turns the cache off for the whole process (to measure or
    // compare cold analyses).
    const char* setting = std::getenv("DEVSURF_ANALYSIS_CACHE");
    m_impl->enabled = !(setting && std::strcmp(setting, "0") == 0);
}

AnalysisCache& AnalysisCache::instance() {
    static AnalysisCache cache;
    return cache;
}

std::shared_ptr<const CachedAnalysis> AnalysisCache::find(int variables,
                                                          const std::vector<int>& colStart,
                                                          const std::vector<int>& rowIndex,
                                                          FactorizationMethod method) {
    const std::uint64_t hash = patternHash(variables, colStart, rowIndex, method);
    std::lock_guard<std::mutex> lock(m_impl->mutex);
    if (!m_impl->enabled) {
        return nullptr;
    }
    auto& entries = m_impl->entries;
    for (auto it = entries.begin(); it != entries.end(); ++it) {
        const CachedAnalysis& entry = **it;
        if (entry.hash == hash && entry.variables == variables && entry.method == method &&
            entry.colStart == colStart && entry.rowIndex == rowIndex) {
            entries.splice(entries.begin(), entries, it);
            ++m_impl->hits;
            return entries.front();
        }
    }
    return nullptr;
}

std::shared_ptr<const CachedAnalysis>
AnalysisCache::insert(std::shared_ptr<const CachedAnalysis> analysis) {
    if (!analysis) {
        return nullptr;
    }
    std::lock_guard<std::mutex> lock(m_impl->mutex);
    if (!m_impl->enabled) {
        return analysis;
    }
    auto& entries = m_impl->entries;
    for (auto it = entries.begin(); it != entries.end(); ++it) {
        const CachedAnalysis& entry = **it;
        if (entry.hash == analysis->hash && entry.variables == analysis->variables &&
            entry.method == analysis->method && entry.colStart == analysis->colStart &&
            entry.rowIndex == analysis->rowIndex) {
            // Another solver decided first (at the same time): its decision stands.
            entries.splice(entries.begin(), entries, it);
            return entries.front();
        }
    }
    entries.push_front(std::move(analysis));
    m_impl->trim();
    return entries.front();
}

void AnalysisCache::clear() {
    std::lock_guard<std::mutex> lock(m_impl->mutex);
    m_impl->entries.clear();
}

std::size_t AnalysisCache::size() const {
    std::lock_guard<std::mutex> lock(m_impl->mutex);
    return m_impl->entries.size();
}

std::size_t AnalysisCache::capacity() const {
    std::lock_guard<std::mutex> lock(m_impl->mutex);
    return m_impl->capacity;
}

void AnalysisCache::setCapacity(std::size_t capacity) {
    std::lock_guard<std::mutex> lock(m_impl->mutex);
    m_impl->capacity = std::max<std::size_t>(capacity, 1);
    m_impl->trim();
}

bool AnalysisCache::isEnabled() const {
    std::lock_guard<std::mutex> lock(m_impl->mutex);
    return m_impl->enabled;
}

void AnalysisCache::setEnabled(bool enabled) {
    std::lock_guard<std::mutex> lock(m_impl->mutex);
    m_impl->enabled = enabled;
    if (!enabled) {
        m_impl->entries.clear();
    }
}

long long AnalysisCache::hits() const {
    std::lock_guard<std::mutex> lock(m_impl->mutex);
    return m_impl->hits;
}

} // namespace devsurf::solver
