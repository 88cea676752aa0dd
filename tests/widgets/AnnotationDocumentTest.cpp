// Annotation in the document: labels loaded from a fragment's octree, set by undo steps that store only what
// they change, a stroke's dabs merged into one step, the legend edited and undone, a used class removed with
// its leaves relabelled, and save → the labels in the .poct, reopen → exactly what was saved.
#include "SceneTestSupport.h"
#include "WidgetTestSupport.h"

#include "stylos/core/annotation/LeafLabels.h"
#include "stylos/core/octree/PackedOctree.h"
#include "stylos/widgets/annotation/LabelStore.h"
#include "stylos/widgets/document/SceneDocument.h"
#include "stylos/widgets/tasks/TaskManager.h"

#include "document/commands/EditLabelsCommand.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QUndoStack>

using stylos::core::annotation::AnnotationLayer;
using stylos::core::annotation::Legend;
using stylos::core::scene::Fragment;
using stylos::core::scene::FragmentId;
using stylos::widgets::EditLabelsCommand;
using stylos::widgets::LabelEdit;
using stylos::widgets::LabelStore;
using stylos::widgets::SceneDocument;
using stylos::widgets::TaskManager;

class AnnotationDocumentTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void mergeKeepsTheFirstBeforeAndTheLastAfter();
    void labelsLoadAndEditsStoreOnlyWhatChanged();
    void aStrokeIsOneUndoStep();
    void refusedEdits();
    void legendEditsUndoAndRemovingAUsedClassRelabels();
    void saveWritesTheLabelsAndReopenGivesThem();
    void aReaderKeepsItsCopy();

private:
    FragmentId addPiece(SceneDocument& document) const;
    std::vector<std::uint8_t> labels(const SceneDocument& document, FragmentId id, AnnotationLayer layer) const
    {
        const auto held = document.labels().labels(id, layer);
        return held ? *held : std::vector<std::uint8_t>{};
    }

    QTemporaryDir m_dir;
    QString m_octreePath;
    SceneDocument::OctreePtr m_octree;
    std::size_t m_leaves = 0;
};

void AnnotationDocumentTest::initTestCase()
{
    QVERIFY(m_dir.isValid());
    m_octreePath = stylos::test::makeOctreeFile(m_dir.path(), "piece.poct");
    auto opened = stylos::core::octree::PackedOctree::open(m_octreePath.toStdString());
    QVERIFY(opened.ok());
    m_octree = std::make_shared<const stylos::core::octree::PackedOctree>(std::move(opened).value());
    m_leaves = stylos::core::annotation::leafCount(*m_octree);
    QVERIFY(m_leaves > 100);
}

FragmentId AnnotationDocumentTest::addPiece(SceneDocument& document) const
{
    Fragment f;
    f.name = "piece";
    f.octreePath = m_octreePath.toStdString();
    return document.addFragment(f, m_octree);
}

void AnnotationDocumentTest::mergeKeepsTheFirstBeforeAndTheLastAfter()
{
    LabelEdit first{1, AnnotationLayer::Material, {2, 5, 9}, {0, 0, 1}, {3, 3, 3}};
    const LabelEdit later{1, AnnotationLayer::Material, {1, 5, 9}, {0, 3, 3}, {4, 0, 1}};
    first.merge(later);
    // Leaf 9 ends where it started (1 → 3 → 1): dropped. Leaf 5: 0 → 3 → 0 dropped too.
    QCOMPARE(first.leaves, (std::vector<std::uint32_t>{1, 2}));
    QCOMPARE(first.before, (std::vector<std::uint8_t>{0, 0}));
    QCOMPARE(first.after, (std::vector<std::uint8_t>{4, 3}));
}

void AnnotationDocumentTest::labelsLoadAndEditsStoreOnlyWhatChanged()
{
    TaskManager tasks;
    SceneDocument document(tasks);
    QSignalSpy changed(&document.labels(), &LabelStore::labelsChanged);
    const FragmentId id = addPiece(document);
    QCOMPARE(changed.count(), 2); // both layers loaded
    QCOMPARE(labels(document, id, AnnotationLayer::Material), std::vector<std::uint8_t>(m_leaves, 0));
    QCOMPARE(labels(document, id, AnnotationLayer::Toolmark), std::vector<std::uint8_t>(m_leaves, 0));

    const std::vector<std::uint32_t> leaves{7, 3, 3, 11, std::uint32_t(m_leaves) + 5}; // a duplicate, one out of range
    QVERIFY(document.setLabels(id, AnnotationLayer::Material, leaves, 2, QStringLiteral("Paint")));
    const auto* step = dynamic_cast<const EditLabelsCommand*>(document.undoStack()->command(1));
    QVERIFY(step);
    QCOMPARE(step->edit().leaves, (std::vector<std::uint32_t>{3, 7, 11}));
    QCOMPARE(step->edit().before, (std::vector<std::uint8_t>{0, 0, 0}));
    QCOMPARE(step->edit().after, (std::vector<std::uint8_t>{2, 2, 2}));
    QCOMPARE(changed.count(), 3);
    QCOMPARE(changed.last().at(2).value<std::vector<std::uint32_t>>(), (std::vector<std::uint32_t>{3, 7, 11}));

    // Painting over with another class: only the leaves that change, with what they held.
    const std::vector<std::uint32_t> over{3, 4};
    QVERIFY(document.setLabels(id, AnnotationLayer::Material, over, 1, QStringLiteral("Paint")));
    const auto* second = dynamic_cast<const EditLabelsCommand*>(document.undoStack()->command(2));
    QCOMPARE(second->edit().leaves, (std::vector<std::uint32_t>{3, 4}));
    QCOMPARE(second->edit().before, (std::vector<std::uint8_t>{2, 0}));
    auto expected = std::vector<std::uint8_t>(m_leaves, 0);
    expected[3] = 1;
    expected[4] = 1;
    expected[7] = 2;
    expected[11] = 2;
    QCOMPARE(labels(document, id, AnnotationLayer::Material), expected);
    QCOMPARE(labels(document, id, AnnotationLayer::Toolmark), std::vector<std::uint8_t>(m_leaves, 0));
    document.undoStack()->undo();
    expected[3] = 2;
    expected[4] = 0;
    QCOMPARE(labels(document, id, AnnotationLayer::Material), expected);
    document.undoStack()->undo();
    QCOMPARE(labels(document, id, AnnotationLayer::Material), std::vector<std::uint8_t>(m_leaves, 0));
    document.undoStack()->redo();
    QCOMPARE(labels(document, id, AnnotationLayer::Material)[7], std::uint8_t(2));
    QCOMPARE(document.labels().count(AnnotationLayer::Material, 2), std::uint64_t(3));
}

void AnnotationDocumentTest::aStrokeIsOneUndoStep()
{
    TaskManager tasks;
    SceneDocument document(tasks);
    const FragmentId id = addPiece(document);
    const int before = document.undoStack()->count();
    const quint64 stroke = document.beginStroke();
    for (std::uint32_t dab = 0; dab < 10; ++dab) {
        const std::vector<std::uint32_t> leaves{dab, dab + 1};
        document.setLabels(id, AnnotationLayer::Toolmark, leaves, 3, QStringLiteral("Brush"), stroke);
    }
    QCOMPARE(document.undoStack()->count(), before + 1);
    const auto* step = dynamic_cast<const EditLabelsCommand*>(document.undoStack()->command(before));
    QCOMPARE(step->edit().size(), std::size_t(11)); // leaves 0..10, each once
    // An eraser stroke that takes back exactly what was painted, in the same stroke: the step disappears.
    const quint64 undoStroke = document.beginStroke();
    const std::vector<std::uint32_t> all{0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10};
    QVERIFY(document.setLabels(id, AnnotationLayer::Toolmark, all, 0, QStringLiteral("Erase"), undoStroke));
    QCOMPARE(document.undoStack()->count(), before + 2); // a new stroke is a new step
    const quint64 third = document.beginStroke();
    QVERIFY(document.setLabels(id, AnnotationLayer::Toolmark, all, 4, QStringLiteral("Brush"), third));
    QVERIFY(document.setLabels(id, AnnotationLayer::Toolmark, all, 0, QStringLiteral("Brush"), third));
    QCOMPARE(document.undoStack()->count(), before + 2); // painted and erased within one stroke: nothing
    document.undoStack()->undo();
    QCOMPARE(labels(document, id, AnnotationLayer::Toolmark)[10], std::uint8_t(3));
    document.undoStack()->undo();
    QCOMPARE(labels(document, id, AnnotationLayer::Toolmark), std::vector<std::uint8_t>(m_leaves, 0));
}

void AnnotationDocumentTest::refusedEdits()
{
    TaskManager tasks;
    SceneDocument document(tasks);
    const FragmentId id = addPiece(document);
    const std::vector<std::uint32_t> leaves{1, 2};
    QVERIFY(!document.setLabels(id, AnnotationLayer::Material, leaves, 77, QStringLiteral("Paint"))); // not a class
    QVERIFY(!document.setLabels(id + 40, AnnotationLayer::Material, leaves, 1, QStringLiteral("Paint"))); // no fragment
    QVERIFY(!document.setLabels(id, AnnotationLayer::Material, leaves, 0, QStringLiteral("Erase"))); // no change
    QVERIFY(!document.setLabels(id, AnnotationLayer::Material, {}, 1, QStringLiteral("Paint")));
    QCOMPARE(document.undoStack()->count(), 1); // only the import
    QVERIFY(!document.removeLegendClass(AnnotationLayer::Material, 99, 0));
    QVERIFY(!document.removeLegendClass(AnnotationLayer::Material, 1, 1));
    QVERIFY(!document.removeLegendClass(AnnotationLayer::Material, 1, 42));
    QVERIFY(!document.setLegend(document.legend()));
    QCOMPARE(document.undoStack()->count(), 1);
}

void AnnotationDocumentTest::legendEditsUndoAndRemovingAUsedClassRelabels()
{
    TaskManager tasks;
    SceneDocument document(tasks);
    const FragmentId id = addPiece(document);
    QSignalSpy legendSpy(&document, &SceneDocument::legendChanged);
    Legend legend = document.legend();
    legend.material[2].name = "plâtre 1950";
    legend.material[2].colour = {1, 2, 3};
    QVERIFY(document.setLegend(legend));
    QCOMPARE(document.legend().material[2].name, std::string("plâtre 1950"));
    QCOMPARE(legendSpy.count(), 1);
    document.undoStack()->undo();
    QCOMPARE(document.legend(), Legend::defaults());
    document.undoStack()->redo();

    // Leaves of class 3 (plaster) in the material layer; class 3 of the tool-mark layer stays untouched.
    const std::vector<std::uint32_t> plaster{5, 6, 7};
    QVERIFY(document.setLabels(id, AnnotationLayer::Material, plaster, 3, QStringLiteral("Paint")));
    QVERIFY(document.setLabels(id, AnnotationLayer::Toolmark, plaster, 3, QStringLiteral("Paint")));
    const int before = document.undoStack()->count();
    QVERIFY(document.removeLegendClass(AnnotationLayer::Material, 3, 4)); // into "unknown"
    QCOMPARE(document.undoStack()->count(), before + 1);
    QVERIFY(!document.legend().find(AnnotationLayer::Material, 3));
    QCOMPARE(labels(document, id, AnnotationLayer::Material)[6], std::uint8_t(4));
    QCOMPARE(labels(document, id, AnnotationLayer::Toolmark)[6], std::uint8_t(3));
    QCOMPARE(document.labels().count(AnnotationLayer::Material, 3), std::uint64_t(0));
    document.undoStack()->undo();
    QCOMPARE(document.legend().material[2].name, std::string("plâtre 1950"));
    QCOMPARE(labels(document, id, AnnotationLayer::Material)[6], std::uint8_t(3));
}


void AnnotationDocumentTest::saveWritesTheLabelsAndReopenGivesThem()
{
    QTemporaryDir dir;
    const QString own = dir.filePath(QStringLiteral("own.poct"));
    QVERIFY(QFile::copy(m_octreePath, own));
    TaskManager tasks;
    std::vector<std::uint8_t> material, toolmark;
    const QString project = dir.filePath(QStringLiteral("site.stylos"));
    {
        SceneDocument document(tasks);
        Fragment f;
        f.name = "own";
        f.octreePath = own.toStdString();
        const FragmentId id = document.addFragment(f, nullptr);
        QSignalSpy loaded(&document, &SceneDocument::loadingFinished);
        QVERIFY(loaded.wait(10000));
        QVERIFY(document.labels().has(id));
        std::vector<std::uint32_t> leaves;
        for (std::uint32_t i = 0; i < m_leaves; i += 3) leaves.push_back(i);
        QVERIFY(document.setLabels(id, AnnotationLayer::Material, leaves, 2, QStringLiteral("Paint")));
        const std::vector<std::uint32_t> one{1};
        QVERIFY(document.setLabels(id, AnnotationLayer::Toolmark, one, 5, QStringLiteral("Paint")));
        QCOMPARE(document.labels().dirty(), std::vector<FragmentId>{id});
        material = labels(document, id, AnnotationLayer::Material);
        toolmark = labels(document, id, AnnotationLayer::Toolmark);
        QString error;
        QVERIFY2(document.saveAs(project, &error), qPrintable(error));
        QVERIFY(document.labels().dirty().empty());
        QVERIFY(!document.isModified());
        // A failing octree write keeps the project modified and names the octree.
        QVERIFY(document.setLabels(id, AnnotationLayer::Toolmark, one, 4, QStringLiteral("Paint")));
        QFile::setPermissions(dir.path(), QFile::ReadOwner | QFile::ExeOwner);
        const bool saved = document.save(&error);
        QFile::setPermissions(dir.path(), QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner);
        if (!saved) { // (root ignores the permissions)
            QVERIFY(error.contains(QStringLiteral("own.poct")));
            QVERIFY(document.isModified());
            QCOMPARE(document.labels().dirty(), std::vector<FragmentId>{id});
        }
        document.undoStack()->undo(); // back to what was saved first
        if (saved) QVERIFY(document.save(&error));
    }
    // The file itself holds them.
    auto file = stylos::core::octree::PackedOctree::open(own.toStdString());
    QVERIFY(file.ok());
    QCOMPARE(stylos::core::annotation::readLeafLabels(*file, AnnotationLayer::Material).value(), material);
    QCOMPARE(stylos::core::annotation::readLeafLabels(*file, AnnotationLayer::Toolmark).value(), toolmark);
    // And the project reopens with exactly them.
    SceneDocument reopened(tasks);
    QSignalSpy loaded(&reopened, &SceneDocument::loadingFinished);
    QString error;
    QVERIFY2(reopened.open(project, &error), qPrintable(error));
    QVERIFY(loaded.wait(10000));
    QVERIFY(loaded.first().at(0).toStringList().isEmpty());
    const FragmentId id = reopened.scene().fragments().at(0).id;
    QCOMPARE(labels(reopened, id, AnnotationLayer::Material), material);
    QCOMPARE(labels(reopened, id, AnnotationLayer::Toolmark), toolmark);
    QVERIFY(reopened.labels().dirty().empty());
}

void AnnotationDocumentTest::aReaderKeepsItsCopy()
{
    TaskManager tasks;
    SceneDocument document(tasks);
    const FragmentId id = addPiece(document);
    const auto held = document.labels().labels(id, AnnotationLayer::Material); // as a background job would
    const std::vector<std::uint32_t> leaves{0};
    QVERIFY(document.setLabels(id, AnnotationLayer::Material, leaves, 1, QStringLiteral("Paint")));
    QCOMPARE((*held)[0], std::uint8_t(0));
    QCOMPARE(labels(document, id, AnnotationLayer::Material)[0], std::uint8_t(1));
}

STYLOS_WIDGET_TEST_MAIN(AnnotationDocumentTest)
#include "AnnotationDocumentTest.moc"
