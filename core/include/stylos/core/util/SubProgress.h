#pragma once
/** @file
 * @brief One part of a long job reported as a sub-range of the caller's progress: update(f) reaches the
 *        parent as from + (to − from) · f, f clamped to [0, 1], and the parent's cancel request is
 *        forwarded. The parent may be null (nothing reported, never cancelled). Thread-safe as the
 *        parent is.
 */
#include "stylos/core/util/Progress.h"

#include <algorithm>

namespace stylos::core {

class SubProgress final : public ProgressSink {
public:
    /** @p from ≤ @p to, both in [0, 1]: the part's share of the whole. */
    SubProgress(ProgressSink* parent, double from, double to) : m_parent(parent), m_from(from), m_to(to) {}

    void update(double fraction) override
    {
        if (m_parent) m_parent->update(m_from + (m_to - m_from) * std::clamp(fraction, 0.0, 1.0));
    }
    bool isCancelRequested() const override { return m_parent && m_parent->isCancelRequested(); }

private:
    ProgressSink* m_parent;
    double m_from;
    double m_to;
};

} // namespace stylos::core
