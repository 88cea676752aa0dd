#include "stylos/widgets/util/WheelGuard.h"

#include <QEvent>
#include <QObject>
#include <QWidget>

namespace stylos::widgets {

namespace {

class WheelGuard final : public QObject {
public:
    using QObject::QObject;

    bool eventFilter(QObject* watched, QEvent* event) override
    {
        if (event->type() != QEvent::Wheel) return false;
        auto* field = qobject_cast<QWidget*>(watched);
        if (!field || field->hasFocus()) return false;
        // Not for this field: ignored, so that Qt offers it to the parents (the scroll area holding the field).
        event->ignore();
        return true;
    }
};

} // namespace

void guardWheel(QWidget* field)
{
    if (!field) return;
    field->setFocusPolicy(Qt::StrongFocus);
    field->installEventFilter(new WheelGuard(field));
}

} // namespace stylos::widgets
