#pragma once

#include "solver/core/term.h"

#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace devsurf::solver {

// A named, contiguous range of variables (e.g. "vertices", "controlPoints", "normals").
struct VariableBlock {
    std::string name;
    int offset = 0;
    int size = 0;
};

// Hard constraints enter the iteration (6) through W (weight w per family); soft energies
// through ε₁ K (their rows are scaled by ε₁ · w); proximity rows (pulling towards the state a
// solve started from) through μ (their rows are scaled by μ · w, where μ follows the
// constraint residual, see Options::proximityFactor); damping rows (residuals that measure a
// change since the last iterate, such as the lengths of a control net re-based before each
// step) through ε₂ like the damping ‖x − x_k‖² itself (their rows are scaled by ε₂ · w), so
// they damp chosen combinations of the step as strongly as ε₂ damps every variable.
enum class TermRole { Constraint, Energy, Proximity, Damping };

struct TermFamily {
    std::string name;
    TermRole role = TermRole::Constraint;
    double weight = 1.0;
    // An energy that pulls towards targets the user sets (a dragged crease's control points):
    // its weighted residual w|φ| caps ε₁ as the constraint residual does (Options::
    // eps1ResidualFactor), so that it still acts where every constraint holds.
    bool drivesEpsilon1 = false;
    // A constraint judged apart, in geometric terms, rather than by the residual tolerance: the
    // kept development (§5), which a sampled mesh matches only up to its discretisation. It
    // weighs as a constraint in every step but leaves the largest constraint residual alone.
    bool judgedApart = false;
};

using FamilyId = int;

// The structure of a guided-projection problem: variables in named blocks and terms grouped
// into weighted families. Adding variables or terms changes the structure (structureId());
// changing weights, fixed flags or term values (targets) does not, so cached symbolic
// factorisations stay valid.
class Problem {
public:
    Problem();
    Problem(Problem&&) noexcept;
    Problem& operator=(Problem&&) noexcept;
    ~Problem();

    // Variables. Returns the offset of the new block. Block names are unique.
    int addVariableBlock(const std::string& name, int size);
    bool hasBlock(const std::string& name) const;
    const VariableBlock& block(const std::string& name) const; // throws std::out_of_range
    const std::vector<VariableBlock>& blocks() const { return m_blocks; }
    int variableCount() const { return m_variableCount; }

    // Fixed variables keep their value exactly (their step is forced to zero).
    void setFixed(int variable, bool fixed = true);
    void setBlockFixed(const std::string& name, bool fixed = true);
    bool isFixed(int variable) const;
    const std::vector<int>& fixedVariables() const { return m_fixedList; }
    std::uint64_t fixedRevision() const { return m_fixedRevision; }

    // Families. Names are unique.
    FamilyId addFamily(const std::string& name, TermRole role, double weight = 1.0);
    FamilyId findFamily(const std::string& name) const; // -1 if absent
    int familyCount() const { return static_cast<int>(m_families.size()); }
    const TermFamily& family(FamilyId id) const {
        return m_families.at(static_cast<std::size_t>(id));
    }
    void setFamilyWeight(FamilyId id, double weight);
    void setFamilyDrivesEpsilon1(FamilyId id, bool drives);
    void setFamilyJudgedApart(FamilyId id, bool apart);

    // Terms. The problem owns them; the returned pointer stays valid for the problem's
    // lifetime and may be used to change the term's values (not its pattern).
    Term* addTerm(FamilyId family, std::unique_ptr<Term> term);
    template <class T> T* add(FamilyId family, std::unique_ptr<T> term) {
        T* raw = term.get();
        addTerm(family, std::move(term));
        return raw;
    }
    int termCount() const { return static_cast<int>(m_terms.size()); }
    const Term& term(int index) const { return *m_terms[static_cast<std::size_t>(index)].term; }
    FamilyId termFamily(int index) const { return m_terms[static_cast<std::size_t>(index)].family; }
    int rowCount() const;

    // Changes (to a process-wide unique value) whenever variables or terms are added.
    std::uint64_t structureId() const { return m_structureId; }

private:
    struct TermEntry {
        std::unique_ptr<Term> term;
        FamilyId family = 0;
    };
    void touchStructure();

    std::vector<VariableBlock> m_blocks;
    int m_variableCount = 0;
    std::vector<char> m_fixed;
    std::vector<int> m_fixedList;
    std::uint64_t m_fixedRevision = 0;
    std::vector<TermFamily> m_families;
    std::vector<TermEntry> m_terms;
    std::uint64_t m_structureId = 0;
};

} // namespace devsurf::solver
