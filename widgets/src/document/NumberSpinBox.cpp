#include "document/NumberSpinBox.h"

#include "stylos/widgets/util/WheelGuard.h"

#include <QLocale>
#include <QRegularExpression>

namespace stylos::widgets {

NumberSpinBox::NumberSpinBox(QWidget* parent) : QDoubleSpinBox(parent) { guardWheel(this); }

std::optional<double> NumberSpinBox::scientific(const QString& text, bool* partial) const
{
    *partial = false;
    QString number = text;
    if (!prefix().isEmpty() && number.startsWith(prefix())) number.remove(0, prefix().size());
    if (!suffix().isEmpty() && number.endsWith(suffix())) number.chop(suffix().size());
    number = number.trimmed();
    if (!number.contains(QLatin1Char('e'), Qt::CaseInsensitive)) return std::nullopt;
    bool ok = false;
    const double value = locale().toDouble(number, &ok);
    if (ok) return value;
    // What may still become a number as the user types: a mantissa and an exponent mark, with or without
    // its sign ("1e", "2,5E-").
    const QString point = QRegularExpression::escape(locale().decimalPoint());
    const QRegularExpression started(QStringLiteral("^[+-]?([0-9]+(%1[0-9]*)?|%1[0-9]+)[eE][+-]?$").arg(point));
    *partial = started.match(number).hasMatch();
    return std::nullopt;
}

QValidator::State NumberSpinBox::validate(QString& text, int& pos) const
{
    bool partial = false;
    if (const auto value = scientific(text, &partial))
        return *value >= minimum() && *value <= maximum() ? QValidator::Acceptable : QValidator::Intermediate;
    if (partial) return QValidator::Intermediate;
    // A plain number out of range: kept as typed, not applied (the plain spin box refused the key that took it
    // out of range, so 720 became 72 and was applied).
    QString number = text;
    if (!prefix().isEmpty() && number.startsWith(prefix())) number.remove(0, prefix().size());
    if (!suffix().isEmpty() && number.endsWith(suffix())) number.chop(suffix().size());
    bool ok = false;
    const double value = locale().toDouble(number.trimmed(), &ok);
    if (ok && (value < minimum() || value > maximum())) return QValidator::Intermediate;
    return QDoubleSpinBox::validate(text, pos);
}

double NumberSpinBox::valueFromText(const QString& text) const
{
    bool partial = false;
    if (const auto value = scientific(text, &partial)) return *value;
    return QDoubleSpinBox::valueFromText(text);
}

} // namespace stylos::widgets
