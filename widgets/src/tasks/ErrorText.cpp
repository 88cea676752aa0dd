#include "tasks/ErrorText.h"

#include <QFileInfo>

namespace stylos::widgets {

QString ErrorText::reason(core::ErrorCode code)
{
    using core::ErrorCode;
    switch (code) {
    case ErrorCode::NotFound: return tr("the file does not exist");
    case ErrorCode::Unreadable: return tr("the file cannot be read");
    case ErrorCode::UnknownFormat: return tr("the file format is not recognised");
    case ErrorCode::Unsupported: return tr("this format is not supported");
    case ErrorCode::Malformed: return tr("the file is malformed");
    case ErrorCode::Truncated: return tr("the file is truncated");
    case ErrorCode::Empty: return tr("the file is empty");
    case ErrorCode::WriteFailed: return tr("the output could not be written");
    // Not only a parameter: no point on the cylinder, too weak a flute signal, too fine a pixel… (the detail follows).
    case ErrorCode::InvalidArgument: return tr("these data and settings do not allow it");
    case ErrorCode::OutOfBudget: return tr("not enough memory for this operation");
    case ErrorCode::Cancelled: return tr("cancelled");
    }
    return tr("unknown error");
}

QString ErrorText::loadFailure(const QString& path, const core::Error& error)
{
    const QString name = QFileInfo(path).fileName();
    return tr("Could not load %1: %2.").arg(name, reason(error.code)) + QLatin1Char('\n') +
           QString::fromStdString(error.message);
}

} // namespace stylos::widgets
