#include "solver/core/problem.h"

#include <algorithm>
#include <atomic>
#include <stdexcept>

namespace devsurf::solver {

namespace {
std::uint64_t nextStructureId() {
    static std::atomic<std::uint64_t> counter{0};
    return ++counter;
}
} // namespace

Problem::Problem() : m_structureId(nextStructureId()) {}
Problem::Problem(Problem&&) noexcept = default;
Problem& Problem::operator=(Problem&&) noexcept = default;
Problem::~Problem() = default;

void Problem::touchStructure() {
    m_structureId = nextStructureId();
}

int Problem::addVariableBlock(const std::string& name, int size) {
    if (size < 0) {
        throw std::invalid_argument("Problem: negative block size");
    }
    if (hasBlock(name)) {
        throw std::invalid_argument("Problem: duplicate block name " + name);
    }
    m_blocks.push_back({name, m_variableCount, size});
    m_variableCount += size;
    m_fixed.resize(static_cast<std::size_t>(m_variableCount), 0);
    touchStructure();
    return m_blocks.back().offset;
}

bool Problem::hasBlock(const std::string& name) const {
    return std::any_of(m_blocks.begin(), m_blocks.end(),
                       [&](const VariableBlock& b) { return b.name == name; });
}

const VariableBlock& Problem::block(const std::string& name) const {
    for (const VariableBlock& b : m_blocks) {
        if (b.name == name) {
            return b;
        }
    }
    throw std::out_of_range("Problem: no variable block " + name);
}

void Problem::setFixed(int variable, bool fixed) {
    if (variable < 0 || variable >= m_variableCount) {
        throw std::out_of_range("Problem: variable index out of range");
    }
    char& flag = m_fixed[static_cast<std::size_t>(variable)];
    if ((flag != 0) == fixed) {
        return;
    }
    flag = fixed ? 1 : 0;
    if (fixed) {
        m_fixedList.insert(std::lower_bound(m_fixedList.begin(), m_fixedList.end(), variable),
                           variable);
    } else {
        m_fixedList.erase(std::lower_bound(m_fixedList.begin(), m_fixedList.end(), variable));
    }
    ++m_fixedRevision;
}

void Problem::setBlockFixed(const std::string& name, bool fixed) {
    const VariableBlock& b = block(name);
    for (int i = 0; i < b.size; ++i) {
        setFixed(b.offset + i, fixed);
    }
}

bool Problem::isFixed(int variable) const {
    return variable >= 0 && variable < m_variableCount &&
           m_fixed[static_cast<std::size_t>(variable)] != 0;
}

FamilyId Problem::addFamily(const std::string& name, TermRole role, double weight) {
    if (findFamily(name) >= 0) {
        throw std::invalid_argument("Problem: duplicate family name " + name);
    }
    m_families.push_back({name, role, weight});
    return static_cast<FamilyId>(m_families.size()) - 1;
}

FamilyId Problem::findFamily(const std::string& name) const {
    for (std::size_t i = 0; i < m_families.size(); ++i) {
        if (m_families[i].name == name) {
            return static_cast<FamilyId>(i);
        }
    }
    return -1;
}

void Problem::setFamilyWeight(FamilyId id, double weight) {
    m_families.at(static_cast<std::size_t>(id)).weight = weight;
}

void Problem::setFamilyDrivesEpsilon1(FamilyId id, bool drives) {
    m_families.at(static_cast<std::size_t>(id)).drivesEpsilon1 = drives;
}

void Problem::setFamilyJudgedApart(FamilyId id, bool apart) {
    m_families.at(static_cast<std::size_t>(id)).judgedApart = apart;
}

Term* Problem::addTerm(FamilyId family, std::unique_ptr<Term> term) {
    if (family < 0 || family >= familyCount()) {
        throw std::out_of_range("Problem: unknown term family");
    }
    if (!term) {
        throw std::invalid_argument("Problem: null term");
    }
    m_terms.push_back({std::move(term), family});
    touchStructure();
    return m_terms.back().term.get();
}

int Problem::rowCount() const {
    int rows = 0;
    for (const TermEntry& t : m_terms) {
        rows += t.term->rowCount();
    }
    return rows;
}

} // namespace devsurf::solver
