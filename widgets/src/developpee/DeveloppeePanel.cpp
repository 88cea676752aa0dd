#include "stylos/widgets/developpee/DeveloppeePanel.h"
#include "stylos/widgets/util/NumberSpinBox.h"

#include "stylos/widgets/developpee/DeveloppeeView.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QFileInfo>
#include <QGridLayout>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QSpinBox>
#include <QToolButton>
#include <QVBoxLayout>

namespace stylos::widgets {

namespace {

using core::unroll::SurfaceKind;

constexpr SurfaceKind Surfaces[] = {SurfaceKind::Cylinder, SurfaceKind::Cone, SurfaceKind::Revolution};
constexpr DeveloppeeShading Shadings[] = {DeveloppeeShading::Skydome, DeveloppeeShading::Light,
                                          DeveloppeeShading::Height};

} // namespace

DeveloppeePanel::DeveloppeePanel(QWidget* parent)
    : QWidget(parent), m_view(new DeveloppeeView(this)), m_surfaceLabel(new QLabel(this)),
      m_surface(new QComboBox(this)), m_shadingLabel(new QLabel(this)), m_shading(new QComboBox(this)),
      m_directionsLabel(new QLabel(this)), m_directions(new QSpinBox(this)), m_pixelLabel(new QLabel(this)),
      m_pixelSize(new NumberSpinBox(this)), m_smooth(new QCheckBox(this)), m_smoothing(new NumberSpinBox(this)),
      m_useAxis(new QCheckBox(this)), m_fit(new QToolButton(this)),
      m_compute(new QPushButton(this)), m_status(new QLabel(this))
{
    setObjectName(QStringLiteral("DeveloppeePanel"));
    m_surface->setObjectName(QStringLiteral("developpeeSurface"));
    m_shading->setObjectName(QStringLiteral("developpeeShading"));
    m_directions->setObjectName(QStringLiteral("developpeeDirections"));
    m_pixelSize->setObjectName(QStringLiteral("developpeePixelSize"));
    m_smooth->setObjectName(QStringLiteral("developpeeSmooth"));
    m_smoothing->setObjectName(QStringLiteral("developpeeSmoothing"));
    m_useAxis->setObjectName(QStringLiteral("developpeeUseAxis"));
    m_fit->setObjectName(QStringLiteral("developpeeFit"));
    m_compute->setObjectName(QStringLiteral("developpeeCompute"));
    m_status->setObjectName(QStringLiteral("developpeeStatus"));

    for (SurfaceKind kind : Surfaces) m_surface->addItem(QString(), static_cast<int>(kind));
    for (DeveloppeeShading shading : Shadings) m_shading->addItem(QString(), static_cast<int>(shading));
    m_directions->setRange(DeveloppeeSettings::MinDirections, DeveloppeeSettings::MaxDirections);
    m_pixelSize->setRange(0.0, 1000.0);
    m_pixelSize->setDecimals(2);
    m_pixelSize->setSingleStep(0.1);
    m_smoothing->setRange(0.0, 20.0);
    m_smoothing->setDecimals(2);
    m_smoothing->setSingleStep(0.1);
    m_status->setWordWrap(true);
    m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_useAxis->setChecked(true);
    m_useAxis->setVisible(false);
    m_compute->setDefault(true);

    auto* bar = new QGridLayout;
    bar->addWidget(m_surfaceLabel, 0, 0);
    bar->addWidget(m_surface, 0, 1);
    bar->addWidget(m_shadingLabel, 0, 2);
    bar->addWidget(m_shading, 0, 3);
    bar->addWidget(m_directionsLabel, 1, 0);
    bar->addWidget(m_directions, 1, 1);
    bar->addWidget(m_pixelLabel, 1, 2);
    bar->addWidget(m_pixelSize, 1, 3);
    bar->addWidget(m_smooth, 2, 0);
    bar->addWidget(m_smoothing, 2, 1);
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(m_useAxis);
    buttons->addStretch(1);
    buttons->addWidget(m_fit);
    buttons->addWidget(m_compute);
    bar->addLayout(buttons, 2, 2, 1, 2);
    bar->setColumnStretch(1, 1);
    bar->setColumnStretch(3, 1);

    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addLayout(bar);
    layout->addWidget(m_view, 1);
    layout->addWidget(m_status);

    setSettings(DeveloppeeSettings{});
    connect(m_shading, &QComboBox::currentIndexChanged, this, &DeveloppeePanel::updateEnabled);
    connect(m_smooth, &QCheckBox::toggled, this, &DeveloppeePanel::updateEnabled);
    connect(m_fit, &QToolButton::clicked, m_view, &DeveloppeeView::fitToWindow);
    connect(m_compute, &QPushButton::clicked, this, [this] {
        if (m_fragmentId != 0 && !m_busy) Q_EMIT computeRequested(settings());
    });
    retranslateUi();
    updateEnabled();
}

DeveloppeeSettings DeveloppeePanel::settings() const
{
    // What the fields show, typed and not yet entered included: a compute started by a shortcut (Ctrl+D) while the
    // focus is still in a field uses the value the user sees (the fields apply on Enter or on leaving only).
    for (QAbstractSpinBox* field : {static_cast<QAbstractSpinBox*>(m_directions), static_cast<QAbstractSpinBox*>(m_pixelSize),
                                    static_cast<QAbstractSpinBox*>(m_smoothing)})
        field->interpretText();
    DeveloppeeSettings s = m_hidden;
    s.surface = static_cast<SurfaceKind>(m_surface->currentData().toInt());
    s.shading = static_cast<DeveloppeeShading>(m_shading->currentData().toInt());
    s.directions = m_directions->value();
    s.pixelSize = m_pixelSize->value() * 1e-3;
    s.smooth = m_smooth->isChecked();
    s.smoothing = m_smoothing->value() * 1e-3;
    s.axis.reset();
    s.radius.reset();
    if (m_axisGuide && m_useAxis->isChecked()) s.axis = m_axisGuide;
    return s;
}

void DeveloppeePanel::setSettings(const DeveloppeeSettings& settings)
{
    m_hidden = settings;
    m_hidden.axis.reset();
    m_hidden.radius.reset();
    m_surface->setCurrentIndex(m_surface->findData(static_cast<int>(settings.surface)));
    m_shading->setCurrentIndex(m_shading->findData(static_cast<int>(settings.shading)));
    m_directions->setValue(settings.directions);
    m_pixelSize->setValue(settings.pixelSize * 1e3);
    m_smooth->setChecked(settings.smooth);
    m_smoothing->setValue(settings.smoothing * 1e3);
    updateEnabled();
}

void DeveloppeePanel::setFragment(quint64 id, const QString& name, const std::optional<core::unroll::Axis>& axisGuide)
{
    m_fragmentId = id;
    m_fragmentName = name;
    m_axisGuide = id != 0 ? axisGuide : std::nullopt;
    m_useAxis->setVisible(m_axisGuide.has_value());
    updateEnabled();
    refreshStatus();
}

void DeveloppeePanel::setBusy(bool busy)
{
    m_busy = busy;
    updateEnabled();
    refreshStatus();
}

void DeveloppeePanel::showResult(const DeveloppeeResult& result)
{
    m_busy = false;
    m_last = result;
    if (result.ok()) m_view->setResult(result);
    updateEnabled();
    refreshStatus();
}

void DeveloppeePanel::clearResult()
{
    m_last.reset();
    m_view->clear();
    updateEnabled();
    refreshStatus();
}

void DeveloppeePanel::setPaintBar(QWidget* bar)
{
    auto* layout = static_cast<QVBoxLayout*>(this->layout());
    bar->setParent(this);
    layout->insertWidget(layout->indexOf(m_view), bar);
}

QString DeveloppeePanel::statusText() const { return m_status->text(); }

QString DeveloppeePanel::fitSummary(const DeveloppeeResult& result)
{
    if (!result.ok()) return result.error;
    const QLocale locale;
    const core::unroll::Surface& surface = result.fit.surface;
    QString summary = tr("%1: %2, radius %3 mm, RMS %4 mm, %5 % inliers; %6 × %7 pixels of %8 mm; %9 s")
        .arg(QFileInfo(result.octreePath).fileName(), DeveloppeeSettings::surfaceName(surface.kind()),
             locale.toString(surface.referenceRadius() * 1e3, 'f', 1), locale.toString(result.fit.rmsResidual * 1e3, 'f', 2),
             locale.toString(result.fit.inlierFraction * 100.0, 'f', 0), locale.toString(result.image.width()),
             locale.toString(result.image.height()), locale.toString(result.unroll.pixelSize * 1e3, 'f', 2),
             locale.toString(result.timings.total, 'f', 1));
    if (result.settings.shading != DeveloppeeShading::Skydome) return summary;
    // The parts' separator is the translator's: a Greek ";" reads as a question mark.
    return summary + tr("; ", "between the parts of a status line") +
           (result.smoothing > 0.0
                ? tr("noise %1 mm smoothed by %2 mm").arg(locale.toString(result.heightNoise * 1e3, 'f', 2),
                                                          locale.toString(result.smoothing * 1e3, 'f', 2))
                : tr("noise %1 mm, raw heights").arg(locale.toString(result.heightNoise * 1e3, 'f', 2)));
}

void DeveloppeePanel::retranslateUi()
{
    m_surfaceLabel->setText(tr("Surface"));
    m_shadingLabel->setText(tr("Shading"));
    m_directionsLabel->setText(tr("Horizon directions"));
    m_pixelLabel->setText(tr("Pixel"));
    for (int i = 0; i < m_surface->count(); ++i)
        m_surface->setItemText(i, DeveloppeeSettings::surfaceName(static_cast<SurfaceKind>(m_surface->itemData(i).toInt())));
    for (int i = 0; i < m_shading->count(); ++i)
        m_shading->setItemText(i, DeveloppeeSettings::shadingName(static_cast<DeveloppeeShading>(m_shading->itemData(i).toInt())));
    m_surface->setToolTip(tr("The surface the développée is unrolled from"));
    m_shading->setToolTip(tr("How the heights become grey: the sky each point sees, one light, or height"));
    m_directions->setToolTip(tr("Skydome shading of the développée: how many azimuths each pixel searches for its "
                                "horizon (more is smoother and slower). Not the 3D view's skydome."));
    m_pixelSize->setSuffix(tr(" mm"));
    m_pixelSize->setSpecialValueText(tr("Automatic"));
    m_pixelSize->setToolTip(tr("Side of a pixel; Automatic uses the octree's leaf size"));
    m_smooth->setText(tr("Smooth noise"));
    m_smooth->setToolTip(tr("Skydome: smooth the scanner's noise out of the heights before the horizon search, so "
                            "that flat, open surfaces read evenly instead of as salt and pepper. Off: the raw heights."));
    m_smoothing->setSuffix(tr(" mm"));
    m_smoothing->setSpecialValueText(tr("Automatic"));
    m_smoothing->setToolTip(tr("Width (Gaussian σ) of the smoothing; Automatic sets it from the noise measured on "
                               "the heights. The status line says what was used."));
    m_useAxis->setText(tr("Use the axis guide"));
    m_useAxis->setToolTip(tr("Fit only the radius about the fragment's axis guide (needed for a fragment)"));
    m_fit->setText(tr("Fit"));
    m_fit->setToolTip(tr("Fit the développée to the view (F)"));
    m_compute->setText(tr("Compute"));
    m_compute->setToolTip(tr("Compute the développée of the selected fragment in the background"));
    m_view->setPlaceholderText(tr("No développée yet: select a fragment and press Compute."));
    refreshStatus();
}

void DeveloppeePanel::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange) retranslateUi();
    QWidget::changeEvent(event);
}

void DeveloppeePanel::updateEnabled()
{
    const bool skydome = static_cast<DeveloppeeShading>(m_shading->currentData().toInt()) == DeveloppeeShading::Skydome;
    m_directions->setEnabled(skydome);
    m_smooth->setEnabled(skydome);
    m_smoothing->setEnabled(skydome && m_smooth->isChecked());
    m_compute->setEnabled(m_fragmentId != 0 && !m_busy);
}

void DeveloppeePanel::refreshStatus()
{
    QString text;
    bool error = false;
    if (m_busy) text = tr("Computing the développée of %1…").arg(m_fragmentName);
    else if (m_last) {
        text = fitSummary(*m_last);
        error = !m_last->ok();
    } else if (m_fragmentId == 0) text = tr("Select a fragment to compute its développée.");
    else text = tr("Press Compute for the développée of %1.").arg(m_fragmentName);
    m_status->setText(text);
    m_status->setStyleSheet(error ? QStringLiteral("color: #c0392b;") : QString());
}

} // namespace stylos::widgets
