#pragma once
/** @file
 * @brief Turns the core's error codes into translated, user-facing text. This is the only place where
 *        an ErrorCode becomes words; the core's own message (file, position, problem) is kept as the detail.
 */
#include "stylos/core/util/Result.h"

#include <QCoreApplication>
#include <QString>

namespace stylos::widgets {

class ErrorText {
    Q_DECLARE_TR_FUNCTIONS(stylos::widgets::ErrorText)

public:
    /** A short translated reason for @p code, to follow a colon: e.g. "the file is truncated". */
    static QString reason(core::ErrorCode code);
    /** "Could not load NAME: REASON.\nDETAIL", naming @p path (file name) and the core's message. */
    static QString loadFailure(const QString& path, const core::Error& error);
};

} // namespace stylos::widgets
