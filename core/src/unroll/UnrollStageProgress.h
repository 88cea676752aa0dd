#pragma once
// Internal to the unroller: one stage of a long job reported as a sub-range of the caller's progress.
#include "stylos/core/util/Progress.h"

#include <cassert>

namespace stylos::core::unroll::detail {

/**
 * @brief Forwards update(f) as from + f · (to − from) to a parent sink (which may be null) and
 *        forwards its cancel request. Thread-safe as the parent is.
 */
class UnrollStageProgress final : public ProgressSink {
public:
    UnrollStageProgress(ProgressSink* parent, double from, double to) : m_parent(parent), m_from(from), m_to(to)
    {
        assert(from <= to && "UnrollStageProgress::UnrollStageProgress(): empty or reversed range");
    }
    void update(double fraction) override
    {
        if (m_parent) m_parent->update(m_from + fraction * (m_to - m_from));
    }
    bool isCancelRequested() const override { return m_parent && m_parent->isCancelRequested(); }

private:
    ProgressSink* m_parent;
    double m_from;
    double m_to;
};

} // namespace stylos::core::unroll::detail
