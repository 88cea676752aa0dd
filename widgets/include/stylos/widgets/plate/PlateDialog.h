#pragma once
/** @file
 * @brief File › Export plate…: the plate's statement (page, orientation, margins, dpi, bits, caption, legend,
 *        panels with their view, 1:N, shading, annotation layer, hatches and fragment; templates that fill the
 *        panels) beside a live preview of the page. The preview is the real plate (stylos_plate's composer and
 *        painter) at a screen resolution, recomputed in a worker thread a moment after the last change; what
 *        does not fit says so ("use 1:18 or smaller") and the Export button waits until it fits.
 *        GUI thread only; the preview's work runs on Qt's global thread pool.
 */
#include "stylos/core/plate/PlateLayout.h"
#include "stylos/core/plate/PlateSources.h"
#include "stylos/core/plate/PlateSpec.h"

#include <QDialog>
#include <QImage>

#include <array>
#include <functional>
#include <memory>
#include <optional>

class QCheckBox;
class QComboBox;
class QDialogButtonBox;
class QDoubleSpinBox;
class QLabel;
class QPlainTextEdit;
class QSpinBox;
class QTableWidget;
class QTimer;

namespace stylos::core::octree {
class PackedOctree;
}

namespace stylos::widgets {

class PlateDialog : public QDialog {
    Q_OBJECT

public:
    /** @p sources: what the plate is made from (the document's fragments, poses, labels and legend). */
    PlateDialog(std::shared_ptr<const core::plate::PlateSources> sources, const core::plate::PlateSpec& spec,
                QWidget* parent = nullptr);
    ~PlateDialog() override;

    /** @brief The 3D view's camera (unit quaternion w, x, y, z, camera → scene): offers "Current view" as a panel
     *         view, drawn orthographically along it. Call before setSpec() for the rows to offer it. */
    void setCurrentCamera(const std::optional<std::array<double, 4>>& camera);

    /** @brief The plate as stated in the dialog now. */
    core::plate::PlateSpec spec() const;
    void setSpec(const core::plate::PlateSpec& spec);

    /** @brief A plate for a project with no stated plate: a développée on A4 landscape at the most detailed usual
     *         scale that fits by its octree's box. Its fragment is sources.fragments[@p preferred] (the one the user
     *         works on), named in the panel, where its octree is there and no other fragment has its name (a panel
     *         names its fragment); else the first visible one.
     *         Its annotation layer is the first of the fragment's in-memory label layers (material, then tool marks)
     *         that holds a class; none where nothing is painted. @p opened gives that octree when the caller holds
     *         it open (else it is read from its file). */
    static core::plate::PlateSpec defaultSpec(
        const core::plate::PlateSources& sources,
        const std::function<std::shared_ptr<const core::octree::PackedOctree>(const core::plate::PlateFragment&)>& opened = {},
        std::optional<std::size_t> preferred = std::nullopt);

    /** @brief Why @p spec's plate does not fit its page, in the workbench's language and number format (the layout's
     *         own message is English): the panel and its size, the print area, the scale or scales that would fit. */
    static QString layoutFailureText(const core::plate::LayoutFailure& failure, const core::plate::PlateSpec& spec);

    // For tests.
    QLabel* previewLabel() const { return m_preview; }
    QLabel* messageLabel() const { return m_message; }
    QTableWidget* panelTable() const { return m_panels; }
    QDialogButtonBox* buttons() const { return m_buttons; }
    QComboBox* templateBox() const { return m_template; }
    /** @brief Whether a preview is being computed or waits for its turn. */
    bool previewPending() const;
    const QImage& previewImage() const { return m_image; }

Q_SIGNALS:
    /** @brief A preview finished (drawn, or refused with a message). */
    void previewUpdated();

private:
    void updateTurnText(); ///< the page box's text for the chosen page
    void addPanelRow(const core::plate::PanelSpec& panel);
    void applyTemplate(int index);
    void schedulePreview();
    void startPreview();
    void retranslateUi();

    std::shared_ptr<const core::plate::PlateSources> m_sources;
    std::optional<std::array<double, 4>> m_camera;
    QComboBox* m_page;
    QCheckBox* m_landscape;
    QDoubleSpinBox* m_margin;
    QSpinBox* m_dpi;
    QComboBox* m_bits;
    QCheckBox* m_legend;
    QPlainTextEdit* m_caption;
    QComboBox* m_template;
    QTableWidget* m_panels;
    QLabel* m_preview;
    QLabel* m_message;
    QDialogButtonBox* m_buttons;
    QTimer* m_timer;
    bool m_onPrintArea = false;          ///< the page is a journal's print area (no margin)
    double m_marginBeforePrintArea = 15; ///< given back when a paper page follows a print area
    QImage m_image;
    bool m_running = false;
    bool m_again = false;
    std::shared_ptr<bool> m_alive;
};

} // namespace stylos::widgets
