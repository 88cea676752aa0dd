#include "AnnotationActions.h"

#include "ToolBarText.h"

#include "AnnotationSync.h"

#include "stylos/widgets/annotation/LassoTool.h"
#include "stylos/widgets/annotation/LegendText.h"
#include "stylos/widgets/document/SceneDocument.h"
#include "stylos/widgets/view3d/ViewportWidget.h"

#include <QAction>
#include <QActionGroup>
#include <QComboBox>
#include <QMenu>
#include <QPixmap>
#include <QToolBar>

namespace stylos::app {

using Layer = core::annotation::AnnotationLayer;

AnnotationActions::AnnotationActions(widgets::SceneDocument& document, widgets::ViewportWidget* viewport,
                                     AnnotationSync* sync, QWidget& window)
    : QObject(&window), m_document(document), m_viewport(viewport), m_sync(sync), m_lasso(new QAction(this)),
      m_erase(new QAction(this)), m_layers(new QActionGroup(this)), m_classBox(new QComboBox(&window))
{
    m_lasso->setObjectName(QStringLiteral("actionLassoTool"));
    m_lasso->setCheckable(true);
    m_lasso->setShortcut(QKeySequence(Qt::Key_K));
    m_erase->setObjectName(QStringLiteral("actionLassoErase"));
    m_erase->setCheckable(true);
    m_classBox->setObjectName(QStringLiteral("lassoClassBox"));
    m_classBox->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    for (const Layer layer : core::annotation::AllAnnotationLayers) {
        QAction* action = m_layers->addAction(QString());
        action->setCheckable(true);
        action->setData(int(layer));
        action->setChecked(layer == Layer::Material);
    }
    if (!m_viewport || !m_sync) {
        m_lasso->setEnabled(false);
        m_layers->setEnabled(false);
    } else {
        m_lasso->setShortcutContext(Qt::WidgetShortcut); // a single key: only while the view has the focus
        m_viewport->addAction(m_lasso);
        connect(m_lasso, &QAction::toggled, this, &AnnotationActions::setLassoActive);
        connect(m_erase, &QAction::toggled, this, [this](bool erase) {
            if (auto* tool = dynamic_cast<widgets::LassoTool*>(m_viewport->tool())) tool->setErase(erase);
        });
        connect(m_layers, &QActionGroup::triggered, this,
                [this](QAction* action) { m_sync->setLayer(Layer(action->data().toInt())); });
        connect(m_sync, &AnnotationSync::layerChanged, this, [this](int layer) {
            for (QAction* action : m_layers->actions()) action->setChecked(action->data().toInt() == layer);
            fillClasses();
        });
    }
    connect(&document, &widgets::SceneDocument::legendChanged, this, &AnnotationActions::fillClasses);
    connect(m_classBox, &QComboBox::activated, this, [this](int index) {
        const Layer layer = m_sync ? m_sync->layer() : Layer::Material;
        const int id = m_classBox->itemData(index).toInt();
        if (id > 0) Q_EMIT classChosen(layer, std::uint8_t(id));
    });
    fillClasses();
    retranslateUi();
}

void AnnotationActions::populate(QMenu& tools, QMenu* shading, QToolBar& toolBar)
{
    tools.addSeparator();
    tools.addAction(m_lasso);
    tools.addAction(m_erase);
    if (shading) {
        shading->addSeparator();
        shading->addActions(m_layers->actions());
    }
    toolBar.addSeparator();
    toolBar.addAction(m_lasso);
    m_classBoxAction = toolBar.addWidget(m_classBox);
    toolBar.addAction(m_erase);
    m_classBoxAction->setVisible(m_lasso->isChecked());
    m_erase->setVisible(m_lasso->isChecked());
}

void AnnotationActions::setExclusiveWith(QAction* other)
{
    if (!other) return;
    connect(other, &QAction::toggled, this, [this](bool on) {
        if (on) m_lasso->setChecked(false);
    });
    connect(m_lasso, &QAction::toggled, other, [other](bool on) {
        if (on) other->setChecked(false);
    }, Qt::DirectConnection);
}

std::uint8_t AnnotationActions::activeClass() const
{
    return std::uint8_t(m_classBox->currentData().toInt());
}

void AnnotationActions::fillClasses()
{
    const Layer layer = m_sync ? m_sync->layer() : Layer::Material;
    const int previous = m_classBox->currentData().toInt();
    m_classBox->clear();
    for (const core::annotation::LegendClass& c : m_document.legend().classes(layer)) {
        QPixmap swatch(12, 12);
        swatch.fill(QColor(c.colour.r, c.colour.g, c.colour.b));
        m_classBox->addItem(QIcon(swatch), widgets::LegendText::className(layer, c), int(c.id)); // as the Legend names it
    }
    // The workbench's active class when it is of this layer, else the one shown before, else the first.
    int index = layer == m_activeLayer && m_activeClass > 0 ? m_classBox->findData(int(m_activeClass)) : -1;
    if (index < 0) index = m_classBox->findData(previous);
    m_classBox->setCurrentIndex(index >= 0 ? index : 0);
}

void AnnotationActions::showActive(Layer layer, std::uint8_t classId)
{
    m_activeLayer = layer;
    m_activeClass = classId;
    // A class of the other layer: the lasso (and the 3D view's annotation shading) take that layer, so a lasso
    // gives the class the Legend highlights (it gave the other layer's class shown in its box).
    if (m_sync && layer != m_sync->layer()) {
        m_sync->setLayer(layer); // layerChanged refills the box with the active class
        return;
    }
    if (const int index = m_classBox->findData(int(classId)); index >= 0) m_classBox->setCurrentIndex(index);
}

void AnnotationActions::setLassoActive(bool active)
{
    if (m_classBoxAction) m_classBoxAction->setVisible(active);
    m_erase->setVisible(active);
    if (!active) {
        if (m_viewport->tool() && m_viewport->tool() == m_tool) m_viewport->resetTool();
        m_tool = nullptr;
        return;
    }
    auto tool = std::make_unique<widgets::LassoTool>(
        [this](const std::vector<core::view::LassoLeaves>& hits, bool erase) { applyLasso(hits, erase); });
    tool->setErase(m_erase->isChecked());
    m_tool = tool.get();
    m_viewport->setTool(std::move(tool));
    m_viewport->setFocus();
}

void AnnotationActions::applyLasso(const std::vector<core::view::LassoLeaves>& hits, bool erase)
{
    const Layer layer = m_sync ? m_sync->layer() : Layer::Material;
    const std::uint8_t classId = erase ? 0 : activeClass();
    if (!erase && classId == 0) {
        Q_EMIT reported(tr("The legend has no class in this layer: add one first"), false);
        return;
    }
    std::size_t changed = 0;
    for (const core::view::LassoLeaves& hit : hits) {
        if (hit.leaves.empty()) continue;
        if (m_document.setLabels(hit.fragment, layer, hit.leaves, classId, erase ? tr("Erase with the lasso") : tr("Lasso in 3D")))
            changed += hit.leaves.size();
    }
    if (hits.empty()) {
        // A selected fragment that is hidden is not lassoed (its cells cannot be seen): say so rather than "none".
        bool hiddenSelected = false, shownSelected = false;
        if (m_viewport)
            for (const core::view::ViewFragment& f : m_viewport->fragments()) {
                hiddenSelected |= f.selected && !f.visible;
                shownSelected |= f.selected && f.visible;
            }
        Q_EMIT reported(hiddenSelected && !shownSelected
                            ? tr("Lasso: the selected fragment is hidden; show it to annotate it in 3D")
                                       : tr("Lasso: no fragment selected or under the lasso"),
                        false);
    } else if (changed == 0) {
        Q_EMIT reported(tr("Lasso: no visible cell changed"), false);
    }
}

void AnnotationActions::retranslateUi()
{
    m_lasso->setText(tr("Annotate in 3D (&lasso)"));
    m_lasso->setStatusTip(tr("Draw a lasso in the 3D view: the visible cells of the selected fragment inside it take "
                             "the chosen class; Ctrl erases; Escape cancels; Alt-drag orbits"));
    m_erase->setText(tr("&Erase with the lasso"));
    m_erase->setStatusTip(tr("The lasso removes the class of the cells it takes"));
    m_classBox->setToolTip(tr("The class the lasso gives"));
    setToolBarText(*m_lasso, tr("3D lasso", "toolbar"));
    setToolBarText(*m_erase, tr("Erase", "toolbar"));
    const QStringList names = {tr("&Material / condition layer"), tr("&Tool mark layer")};
    for (QAction* action : m_layers->actions()) action->setText(names.value(action->data().toInt()));
    fillClasses(); // the default classes' names in the new language
}

} // namespace stylos::app
