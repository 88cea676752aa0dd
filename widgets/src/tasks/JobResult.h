#pragma once
/** @file
 * @brief The task body the widgets' jobs share (DeveloppeeJob, SkydomeJob): run the job, add its value to
 *        the promise, nothing when it was cancelled, or the failure the job makes of the core's error
 *        (a result carrying a translated message) — so the GUI side always gets one result or none.
 */
#include "stylos/core/util/Progress.h"
#include "stylos/core/util/Result.h"

#include <QPromise>

#include <utility>

namespace stylos::widgets {

/**
 * @brief Adds to @p promise what @p run(&progress) gives: its value, or @p failure(error) for an error
 *        other than Cancelled; nothing when cancelled (by the error or by @p progress).
 */
template <typename R, typename Run, typename Failure>
void deliverJobResult(QPromise<R>& promise, core::ProgressSink& progress, Run&& run, Failure&& failure)
{
    auto computed = run(&progress);
    if (!computed && computed.error().code == core::ErrorCode::Cancelled) return;
    if (progress.isCancelRequested()) return;
    if (computed) promise.addResult(std::move(computed).value());
    else promise.addResult(failure(computed.error()));
}

} // namespace stylos::widgets
