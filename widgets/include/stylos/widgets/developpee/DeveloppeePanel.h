#pragma once
/** @file
 * @brief The Développée dock's contents: a settings bar (surface, shading, skydome directions, pixel size,
 *        "use the axis guide" when the fragment has one), a Compute button, the DeveloppeeView and a status
 *        line with the fit (surface, radius, RMS residual) or the last error.
 *
 * The dock does not run anything: Compute emits computeRequested(settings) for the current fragment
 * (setFragment()), the window starts a DeveloppeeJob on its TaskManager and hands the result back with
 * showResult(). Settings the bar does not show (light direction, contrast stretch) are kept from
 * setSettings(). GUI thread only.
 */
#include "stylos/core/unroll/Surface.h"
#include "stylos/widgets/developpee/DeveloppeeJob.h"
#include "stylos/widgets/developpee/DeveloppeeSettings.h"

#include <QString>
#include <QWidget>

#include <optional>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QSpinBox;
class QToolButton;

namespace stylos::widgets {

class DeveloppeeView;

class DeveloppeePanel : public QWidget {
    Q_OBJECT

public:
    explicit DeveloppeePanel(QWidget* parent = nullptr);

    DeveloppeeView* view() const { return m_view; }
    /** @brief Puts @p bar (the painting bar, owned from then on) between the settings and the view. */
    void setPaintBar(QWidget* bar);

    /** @brief The bar's settings, with the axis guide when "use the axis guide" is on. */
    DeveloppeeSettings settings() const;
    /** @brief Shows @p settings in the bar (its axis is ignored: the axis comes from setFragment()). */
    void setSettings(const DeveloppeeSettings& settings);

    /**
     * @brief The fragment Compute works on; 0 for none (Compute disabled). @p axisGuide: the fragment's
     *        axis guide in its own (octree) frame, offered as "Use the axis guide" (checked by default).
     */
    void setFragment(quint64 id, const QString& name, const std::optional<core::unroll::Axis>& axisGuide = {});
    /** @brief The axis "Use the axis guide" offers for the current fragment (its own frame), if any. */
    const std::optional<core::unroll::Axis>& axisGuide() const { return m_axisGuide; }
    quint64 fragmentId() const { return m_fragmentId; }

    /** @brief While busy, Compute is disabled and the status says a computation runs. */
    void setBusy(bool busy);
    bool isBusy() const { return m_busy; }

    /** @brief Ends the busy state; a success goes to the view and the status, a failure to the status only. */
    void showResult(const DeveloppeeResult& result);
    /** @brief Shows no développée (the view's placeholder, the status for the current fragment). */
    void clearResult();
    /** @brief The status line's text. */
    QString statusText() const;
    /** @brief "NAME: Cylinder, radius 550.0 mm, RMS 0.42 mm, 98 % inliers; 3456 × 512 pixels of 1.00 mm; 2.3 s". */
    static QString fitSummary(const DeveloppeeResult& result);

    void retranslateUi();

Q_SIGNALS:
    /** @brief Compute was pressed for fragmentId() with these settings. */
    void computeRequested(const stylos::widgets::DeveloppeeSettings& settings);

protected:
    void changeEvent(QEvent* event) override;

private:
    void updateEnabled();
    void refreshStatus();

    DeveloppeeView* m_view;
    QLabel* m_surfaceLabel;
    QComboBox* m_surface;
    QLabel* m_shadingLabel;
    QComboBox* m_shading;
    QLabel* m_directionsLabel;
    QSpinBox* m_directions;
    QLabel* m_pixelLabel;
    QDoubleSpinBox* m_pixelSize;
    QCheckBox* m_smooth;
    QDoubleSpinBox* m_smoothing;
    QCheckBox* m_useAxis;
    QToolButton* m_fit;
    QPushButton* m_compute;
    QLabel* m_status;

    DeveloppeeSettings m_hidden; ///< the settings the bar does not show
    quint64 m_fragmentId = 0;
    QString m_fragmentName;
    std::optional<core::unroll::Axis> m_axisGuide;
    bool m_busy = false;
    std::optional<DeveloppeeResult> m_last; ///< the last result shown (for the status after a language change)
};

} // namespace stylos::widgets
