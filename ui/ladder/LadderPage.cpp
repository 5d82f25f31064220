// SPDX-License-Identifier: GPL-3.0-or-later
#include "LadderPage.h"

#include "ConfigOptionDialog.h"
#include "ElementDialog.h"
#include "ElementIcon.h"
#include "LadderView.h"
#include "NetworkItem.h"
#include "NetworkPainter.h"
#include "StepHeaderItem.h"
#include "document/ProjectDocument.h"
#include "ladder/NetworkText.h"
#include "ladder/TextToLadder.h"
#include "lang/Parser.h"
#include "project/SaveFileCommit.h"
#include "project/Sequences.h"
#include "project/UnitSettings.h"
#include "project/UnitText.h"
#include "shell/PageTitle.h"
#include "shell/UnitCaption.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QClipboard>
#include <QDir>
#include <QDrag>
#include <QFileDialog>
#include <QGraphicsScene>
#include <QGraphicsSimpleTextItem>
#include <QInputDialog>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QMessageBox>
#include <QMimeData>
#include <QPainter>
#include <QPdfWriter>
#include <QPrintDialog>
#include <QPrinter>
#include <QSaveFile>
#include <QScrollBar>
#include <QToolBar>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace rs::ui {

namespace {

constexpr char kNetworksMimeType[] = "application/x-rungsmith-networks";
constexpr qreal kNetworkGap = 4;

QString signatureOf(const ladder::ElementLayout& element) {
    return QStringLiteral("%1|%2|%3|%4|%5")
        .arg(static_cast<int>(element.kind))
        .arg(element.name, element.address, element.text)
        .arg(element.output >= 0);
}

std::vector<QString> signaturesOf(const ladder::NetworkLayout& layout) {
    std::vector<QString> signatures;
    for (const auto& element : layout.elements)
        signatures.push_back(signatureOf(element));
    return signatures;
}

// The condition node at a path, or nullptr.
const ladder::Circuit* nodeAt(const ladder::Network& network, const ladder::ElementPath& path) {
    if (path.item >= network.items.size())
        return nullptr;
    const auto* rung = std::get_if<ladder::Rung>(&network.items[path.item]);
    if (!rung || !rung->condition)
        return nullptr;
    const ladder::Circuit* node = &*rung->condition;
    for (std::size_t index : path.node) {
        if (index >= node->parts.size())
            return nullptr;
        node = &node->parts[index];
    }
    return node;
}

// Element numbers (pre-order from 1) and columns of a condition's elements.
void numberElements(const ladder::Circuit& circuit, std::uint16_t& number,
                    std::vector<std::pair<std::uint16_t, int>>& columns) {
    const std::uint16_t mine = number++;
    if (circuit.isElement()) {
        columns.emplace_back(mine, circuit.location.column);
        return;
    }
    for (const auto& part : circuit.parts)
        numberElements(part, number, columns);
}

} // namespace

LadderPage::LadderPage(QWidget* parent)
    : QWidget(parent), m_title(new PageTitle(this)), m_toolBar(new QToolBar(this)),
      m_scene(new QGraphicsScene(this)), m_view(new LadderView(m_scene, this)),
      m_status(new QLabel(this)) {
    setObjectName(QStringLiteral("ladderPage"));
    m_view->setObjectName(QStringLiteral("ladderView"));
    m_toolBar->setObjectName(QStringLiteral("ladderToolBar"));
    m_status->setObjectName(QStringLiteral("ladderStatus"));
    m_status->setWordWrap(true);
    m_drawing = drawingFor(palette());
    m_view->setBackgroundBrush(m_drawing.style.background);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_title);
    layout->addWidget(m_toolBar);
    layout->addWidget(m_view, 1);
    layout->addWidget(m_status);
    m_editingHint =
        tr("No networks yet. Press Ins, or right-click > New Network, then insert the network's "
           "output (L coil, S set, R reset, J jump ...) and its contacts.");
    m_emptyHint = m_scene->addSimpleText(m_editingHint);
    m_emptyHint->setVisible(false);
    createActions();
    m_toolBar->setIconSize(kElementIconSize);
    drawElementIcons();
    m_view->keyHandler = [this](QKeyEvent* event) {
        return handleKey(event);
    };
    connect(m_view, &LadderView::pressed, this, &LadderPage::pressed);
    connect(m_view, &LadderView::doubleClicked, this, &LadderPage::doubleClicked);
    connect(m_view, &LadderView::menuRequested, this, &LadderPage::showMenu);
    connect(m_view, &LadderView::dragStarted, this, &LadderPage::startDrag);
    connect(m_view, &LadderView::dropped, this, &LadderPage::drop);
    connect(m_view, &LadderView::clipboardRequested, this, [this](int key) {
        if (key == Qt::Key_X)
            cutNetworks();
        else if (key == Qt::Key_C)
            copyNetworks();
        else
            pasteNetworks();
    });
    setFocusProxy(m_view);
}

LadderPage::~LadderPage() = default;

QAction* LadderPage::action(const QString& objectName) const {
    return findChild<QAction*>(objectName);
}

void LadderPage::createActions() {
    auto add = [this](const QString& name, const QString& text, const QString& tip,
                      auto slot) -> QAction* {
        auto* action = new QAction(text, this);
        action->setObjectName(name);
        action->setToolTip(tip);
        connect(action, &QAction::triggered, this, slot);
        return action;
    };
    QAction* text = add(QStringLiteral("ladderTextAction"), tr("Text"),
                        tr("Show this code as text"), [this] { emit textRequested(); });
    m_toolBar->addAction(text);
    m_toolBar->addSeparator();

    m_placementGroup = new QActionGroup(this);
    const struct {
        Placement placement;
        const char* name;
        QString text;
        QString tip;
    } placements[] = {
        {Placement::After, "placeAfterAction", tr("After"),
         tr("Insert in series after the selection (key ])")},
        {Placement::Before, "placeBeforeAction", tr("Before"),
         tr("Insert in series before the selection (key [)")},
        {Placement::Parallel, "placeParallelAction", tr("Parallel"),
         tr("Insert in a parallel branch around the selection (key \\)")},
    };
    for (const auto& p : placements) {
        QAction* action = add(QLatin1String(p.name), p.text, p.tip,
                              [this, placement = p.placement] { setPlacement(placement); });
        action->setCheckable(true);
        action->setChecked(p.placement == m_placement);
        m_placementGroup->addAction(action);
        m_toolBar->addAction(action);
    }
    m_toolBar->addSeparator();
    for (const ElementKindInfo& info : ladder::elementKinds()) {
        QAction* action = add(
            QStringLiteral("insert%1Action").arg(static_cast<int>(info.kind)),
            QString::fromLatin1(info.picture),
            tr("%1 (key %2)")
                .arg(
                    ElementKinds::name(info.kind),
                    QKeySequence(QLatin1String(info.insertKey)).toString(QKeySequence::NativeText)),
            [this, kind = info.kind] { insertElement(kind); });
        m_toolBar->addAction(action);
        if (info.kind == ElementKind::Comparison)
            m_toolBar->addSeparator();
    }
    m_toolBar->addSeparator();
    m_toolBar->addAction(add(QStringLiteral("ladderDeleteAction"), tr("Delete"),
                             tr("Delete the selected element (Del)"),
                             [this] { deleteSelection(); }));
    m_toolBar->addAction(add(QStringLiteral("newNetworkAction"), tr("New Network"),
                             tr("A new network below the selected one (Ins)"),
                             [this] { newNetwork(); }));
    m_toolBar->addAction(add(QStringLiteral("expandAllAction"), tr("Expand All"),
                             tr("Show the rungs of every network"),
                             [this] { setAllCollapsed(false); }));
    m_toolBar->addAction(add(QStringLiteral("collapseAllAction"), tr("Collapse All"),
                             tr("Show only the comments of the networks"),
                             [this] { setAllCollapsed(true); }));
    m_toolBar->addSeparator();
    m_toolBar->addAction(add(QStringLiteral("editNetworkAction"), tr("Edit Network"),
                             tr("Gather the next edits of this network until Update (key E)"),
                             [this] { enterEditMode(); }));
    m_toolBar->addAction(add(QStringLiteral("updateNetworkAction"), tr("Update"),
                             tr("Keep the edits of the network as one step (F3)"),
                             [this] { updateNetwork(); }));
    m_toolBar->addAction(add(QStringLiteral("undoNetworkAction"), tr("Undo Network"),
                             tr("Drop the edits of the network (F2)"), [this] { undoNetwork(); }));
    m_toolBar->addSeparator();
    QAction* zoomIn = add(QStringLiteral("zoomInAction"), tr("Zoom In"), tr("Zoom in (Ctrl++)"),
                          [this] { m_view->zoomIn(); });
    zoomIn->setShortcuts({QKeySequence::ZoomIn, QKeySequence(QStringLiteral("Ctrl+="))});
    QAction* zoomOut = add(QStringLiteral("zoomOutAction"), tr("Zoom Out"), tr("Zoom out (Ctrl+-)"),
                           [this] { m_view->zoomOut(); });
    zoomOut->setShortcut(QKeySequence::ZoomOut);
    QAction* zoomReset = add(QStringLiteral("zoomResetAction"), tr("100%"),
                             tr("Actual size (Ctrl+0)"), [this] { m_view->setZoom(1); });
    zoomReset->setShortcut(QKeySequence(QStringLiteral("Ctrl+0")));
    for (QAction* action : {zoomIn, zoomOut, zoomReset}) {
        action->setShortcutContext(Qt::WidgetWithChildrenShortcut);
        addAction(action);
        m_toolBar->addAction(action);
    }
    m_toolBar->addSeparator();
    m_toolBar->addAction(add(QStringLiteral("printLadderAction"), tr("Print..."),
                             tr("Print the networks of this page"), [this] { print(); }));
    m_toolBar->addAction(add(QStringLiteral("exportPdfAction"), tr("PDF..."),
                             tr("Export the networks of this page as PDF"),
                             [this] { exportPdf({}); }));
}

void LadderPage::setPlacement(Placement placement) {
    m_placement = placement;
    const char* names[] = {"placeAfterAction", "placeBeforeAction", "placeParallelAction"};
    action(QLatin1String(names[static_cast<int>(placement)]))->setChecked(true);
}

void LadderPage::changeEvent(QEvent* event) {
    QWidget::changeEvent(event);
    if (event->type() != QEvent::PaletteChange)
        return;
    // The theme changed: the drawing follows the window's colours.
    const LadderDrawing colours = drawingFor(palette());
    m_drawing.style = colours.style;
    m_drawing.selection = colours.selection;
    m_drawing.markedNetwork = colours.markedNetwork;
    m_drawing.problem = colours.problem;
    m_drawing.editing = colours.editing;
    m_view->setBackgroundBrush(m_drawing.style.background);
    drawElementIcons();
    repaintItems();
}

void LadderPage::drawElementIcons() {
    for (const ElementKindInfo& info : ladder::elementKinds())
        action(QStringLiteral("insert%1Action").arg(static_cast<int>(info.kind)))
            ->setIcon(elementIcon(info.kind, m_drawing.style));
}

// ----- showing the model

void LadderPage::showUnit(ProjectDocument* document, int station, int sequence) {
    if (m_document != document) {
        if (m_document)
            disconnect(m_document, nullptr, this, nullptr);
        if (document) {
            connect(document, &ProjectDocument::changed, this, &LadderPage::followModel);
            connect(document, &ProjectDocument::pathChanged, this, &LadderPage::updateTitle);
        }
    }
    const bool samePage = document == m_document && station == m_station && sequence == m_sequence;
    m_document = document;
    m_station = station;
    m_sequence = sequence;
    if (!samePage) {
        m_pending.reset();
        m_editSession.reset();
        m_drawing.editingNetwork.reset();
        m_drawing.cursor = {};
        m_drawing.marked.clear();
        m_drawing.problems.clear();
        for (auto& step : m_items)
            for (NetworkItem* item : step)
                delete item;
        m_items.clear();
        for (StepHeaderItem* header : m_headers)
            delete header;
        m_headers.clear();
    }
    rebuild();
    updateTitle();
    if (!samePage) {
        m_view->verticalScrollBar()->setValue(0);
        if (stepCount() > 0 && networkCount(0) > 0)
            setCursor({0, 0, std::nullopt, std::nullopt, -1});
    }
}

void LadderPage::updateTitle() {
    if (!m_document) {
        m_title->setTitle({});
        return;
    }
    m_title->setTitle(pageTitle());
    // The keys that work now: simulating, the page is for watching and forcing.
    m_title->setSubtitle(
        isLive() ? tr("Simulating: a click or Space on an input toggles it; a right click, the "
                      "Menu key or Shift+F10 forces any element's variable. Editing ends the "
                      "simulation.")
                 : tr("Keys: C contact, / NC, P N edges, O U F timers, = compare, L coil, "
                      "S R T latches, J jump, Q sequence reset, + arithmetic; [ ] \\ "
                      "before, after, parallel; Enter properties; Del delete; Ins new "
                      "network."));
}

QString LadderPage::pageTitle() const {
    if (!m_document)
        return {};
    const QString unit = unitCaption(m_document->project(), m_station);
    return m_sequence == 0 ? tr("%1 — PLC Code").arg(unit)
                           : tr("%1 — Sequence %2").arg(unit).arg(m_sequence);
}

void LadderPage::followModel() {
    if (m_editSession) {
        m_editSession.reset();
        m_drawing.editingNetwork.reset();
        setMessage(tr("The project changed, so the network's edits were dropped."));
    }
    rebuild();
    updateTitle();
}

void LadderPage::rebuild() {
    m_steps.clear();
    m_stepComments.clear();
    m_undrawnLines = 0;
    if (m_document) {
        const project::Project& project = m_document->project();
        std::vector<lang::Line> names = project.program.preamble;
        for (const auto& unit : project.program.units) {
            if (unit.station() != m_station)
                continue;
            names.insert(names.end(), unit.declarations.begin(), unit.declarations.end());
            if (const std::size_t lines = ladder::sequenceLines(unit, m_sequence);
                lines > ladder::kMostDrawnLines) {
                m_undrawnLines = lines;
                continue;
            }
            for (auto& page : ladder::unitLadder(unit))
                if (page.address.sequence == m_sequence)
                    m_steps.push_back(std::move(page));
            for (const auto& step : unit.steps)
                if (step.address.sequence == m_sequence)
                    m_stepComments.push_back(
                        QString::fromStdString(step.comment.value_or(std::string())).trimmed());
        }
        if (names != m_names || m_namesVersion == 0) {
            m_names = std::move(names);
            m_symbols = ladder::SymbolTable::of(project.program, m_station);
            ++m_namesVersion;
        }
    }
    if (m_undrawnLines > 0) {
        m_steps.clear();
        m_stepComments.clear();
        m_pending.reset();
    } else if (m_steps.empty() && m_document && m_sequence == 0) {
        m_steps.push_back({{m_station, 0, 0}, {}, {}});
        m_stepComments.emplace_back();
    }
    if (m_pending) {
        auto [step, index] = *m_pending;
        if (step < stepCount() && index <= networkCount(step)) {
            auto& page = m_steps[step];
            const std::uint32_t first =
                index < networkCount(step) ? page.firstStatements[index]
                : index > 0                ? page.firstStatements[index - 1] +
                                  ladder::statementCount(page.ladder.networks[index - 1])
                            : 0;
            page.ladder.networks.insert(page.ladder.networks.begin() + index, ladder::Network{});
            page.firstStatements.insert(page.firstStatements.begin() + index, first);
        } else {
            m_pending.reset();
        }
    }

    // Items are kept by place; an item lays out again only when its network changed.
    while (m_items.size() > m_steps.size()) {
        for (NetworkItem* item : m_items.back())
            delete item;
        m_items.pop_back();
        delete m_headers.back();
        m_headers.pop_back();
    }
    for (std::size_t s = 0; s < m_steps.size(); ++s) {
        const auto& page = m_steps[s];
        const QString stepText =
            QStringLiteral("%1   %2   %3")
                .arg(tr("Step %1").arg(page.address.step),
                     QString::fromStdString(lang::toString(page.address)), m_stepComments[s]);
        if (s >= m_items.size()) {
            m_items.emplace_back();
            m_headers.push_back(
                new StepHeaderItem(&m_drawing, m_sequence, page.address.step, stepText));
            m_scene->addItem(m_headers.back());
        }
        m_headers[s]->setText(page.address.step, stepText.trimmed());
        m_headers[s]->setVisible(m_sequence != 0);
        auto& items = m_items[s];
        const int count = static_cast<int>(page.ladder.networks.size());
        while (static_cast<int>(items.size()) > count) {
            delete items.back();
            items.pop_back();
        }
        for (int n = 0; n < count; ++n) {
            if (n >= static_cast<int>(items.size())) {
                items.push_back(new NetworkItem(&m_drawing, static_cast<int>(s), n));
                m_scene->addItem(items.back());
            }
            ladder::LayoutContext context;
            context.number = n + 1;
            context.title = tr("Network %1").arg(n + 1);
            context.firstStatement = page.firstStatements[n];
            context.symbols = &m_symbols;
            items[n]->setIndex(static_cast<int>(s), n);
            items[n]->setNetwork(page.ladder.networks[n], context, m_namesVersion);
        }
    }
    placeItems();
    // The cursor stays where it was while that place exists.
    LadderCursor& cursor = m_drawing.cursor;
    if (cursor.valid() &&
        (cursor.step >= stepCount() || cursor.network >= networkCount(cursor.step)))
        cursor = {};
    else if (cursor.valid() && !cursor.wholeNetwork() && !cursorElement() &&
             !(cursor.node &&
               nodeAt(m_steps[cursor.step].ladder.networks[cursor.network], *cursor.node)))
        cursor = {cursor.step, cursor.network, std::nullopt, std::nullopt, -1};
    updateActions();
    repaintItems();
}

void LadderPage::placeItems() {
    qreal y = 0;
    qreal width = 400;
    for (std::size_t s = 0; s < m_items.size(); ++s) {
        if (m_headers[s]->isVisible()) {
            m_headers[s]->setPos(0, y);
            y += StepHeaderItem::kHeight + kNetworkGap;
        }
        for (NetworkItem* item : m_items[s]) {
            if (item->pos() != QPointF(0, y))
                item->setPos(0, y);
            const QRectF bounds = item->boundingRect();
            y += bounds.height() + kNetworkGap;
            width = std::max(width, bounds.width());
        }
    }
    for (StepHeaderItem* header : m_headers)
        header->setWidth(width);
    // An empty page says how to begin.
    const bool empty =
        std::all_of(m_items.begin(), m_items.end(), [](const auto& step) { return step.empty(); });
    m_emptyHint->setVisible(empty && m_document);
    m_emptyHint->setText(
        m_undrawnLines > 0
            ? tr("This code has %1 lines, more than the ladder page draws (%2).\nIts text page "
                 "(F6) shows and edits it.")
                  .arg(m_undrawnLines)
                  .arg(ladder::kMostDrawnLines)
        : isLive() ? tr("No networks in this code.")
                   : m_editingHint);
    m_emptyHint->setBrush(m_drawing.style.commentInk);
    m_emptyHint->setPos(NetworkItem::kGutter, y + 16);
    if (empty)
        y += 60;
    m_scene->setSceneRect(0, 0, width, std::max<qreal>(y, 1));
}

void LadderPage::repaintItems() {
    m_view->viewport()->update();
}

int LadderPage::networkCount(int step) const {
    return step >= 0 && step < stepCount() ? static_cast<int>(m_steps[step].ladder.networks.size())
                                           : 0;
}

NetworkItem* LadderPage::networkItem(int step, int network) const {
    if (step < 0 || step >= static_cast<int>(m_items.size()) || network < 0 ||
        network >= static_cast<int>(m_items[step].size()))
        return nullptr;
    return m_items[step][network];
}

void LadderPage::setMessage(const QString& message) {
    m_status->setText(message);
}

QString LadderPage::message() const {
    return m_status->text();
}

void LadderPage::updateActions() {
    // An undrawn page offers no edits: they would act on a ladder it does not hold.
    const bool editable = m_document && !isLive() && m_undrawnLines == 0;
    m_view->setEnabled(m_undrawnLines == 0);
    // Viewing stays possible while simulating; only editing stops.
    static const QStringList viewing = {
        QStringLiteral("ladderTextAction"), QStringLiteral("printLadderAction"),
        QStringLiteral("exportPdfAction"), QStringLiteral("expandAllAction"),
        QStringLiteral("collapseAllAction")};
    for (QAction* action : m_toolBar->actions())
        if (!viewing.contains(action->objectName()) &&
            !action->objectName().startsWith(QLatin1String("zoom")))
            action->setEnabled(editable);
    action(QStringLiteral("updateNetworkAction"))->setEnabled(editable && isEditingNetwork());
    action(QStringLiteral("undoNetworkAction"))->setEnabled(editable && isEditingNetwork());
}

// ----- live state

void LadderPage::setLiveState(const LadderLiveState* state) {
    const bool changedMode = (state == nullptr) != (m_drawing.live == nullptr);
    m_drawing.live = state;
    if (changedMode) {
        if (state && m_editSession)
            undoNetwork();
        updateActions();
        updateTitle();
        placeItems();
    }
    repaintItems();
}

QColor LadderPage::elementColor(std::uint32_t statement, std::uint16_t element) const {
    if (m_drawing.live && m_drawing.live->power.conducts(statement, element))
        return m_drawing.style.powered;
    return m_drawing.style.ink;
}

// ----- diagnostics

void LadderPage::setDiagnostics(const lang::Diagnostics& diagnostics) {
    m_drawing.problems.clear();
    if (!m_document || diagnostics.empty()) {
        repaintItems();
        return;
    }
    // Statements numbered in file order, as the compiler numbers them, with
    // the lines and columns of the unit's text.
    const lang::ParseResult parsed =
        lang::parse(project::unitText(m_document->project(), m_station));
    struct Place {
        int line;
        std::uint32_t statement;
        std::vector<std::pair<std::uint16_t, int>> columns;
    };
    std::vector<Place> places;
    std::uint32_t number = 0;
    for (const auto& unit : parsed.document.units)
        for (const auto& step : unit.steps)
            for (const auto& line : step.lines)
                if (const auto* statement = std::get_if<lang::Statement>(&line.body)) {
                    Place place{statement->location.line, number++, {}};
                    if (statement->condition) {
                        std::uint16_t element = 1;
                        numberElements(ladder::toCircuit(*statement->condition), element,
                                       place.columns);
                    }
                    places.push_back(std::move(place));
                }
    for (const auto& diagnostic : diagnostics) {
        const auto place = std::find_if(places.begin(), places.end(),
                                        [&](const Place& p) { return p.line == diagnostic.line; });
        if (place == places.end())
            continue;
        std::uint16_t element = 0;
        for (const auto& [candidate, column] : place->columns)
            if (column <= diagnostic.column)
                element = candidate;
        QString& text = m_drawing.problems[{place->statement, element}];
        if (!text.isEmpty())
            text += QLatin1Char('\n');
        text += QString::fromStdString(diagnostic.message);
    }
    repaintItems();
}

// ----- selection

const ladder::ElementLayout* LadderPage::cursorElement() const {
    const LadderCursor& cursor = m_drawing.cursor;
    NetworkItem* item = networkItem(cursor.step, cursor.network);
    if (!item || cursor.wholeNetwork())
        return nullptr;
    for (const auto& element : item->layout().elements) {
        if (cursor.node && element.output < 0 && element.path == *cursor.node)
            return &element;
        if (cursor.output && element.output == cursor.outputIndex &&
            element.path.item == cursor.output->item)
            return &element;
    }
    return nullptr;
}

void LadderPage::setCursor(const LadderCursor& cursor) {
    m_drawing.cursor = cursor;
    QString text;
    if (const ladder::ElementLayout* element = cursorElement()) {
        const auto found = m_drawing.problems.find({element->statement, element->element});
        if (found != m_drawing.problems.end())
            text = found->second;
        else if (element->output >= 0)
            if (const auto whole = m_drawing.problems.find({element->statement, 0});
                whole != m_drawing.problems.end())
                text = whole->second;
    }
    setMessage(text);
    ensureCursorVisible();
    repaintItems();
}

bool LadderPage::selectElement(std::uint32_t statement, std::uint16_t element) {
    for (std::size_t s = 0; s < m_items.size(); ++s)
        for (NetworkItem* item : m_items[s])
            for (const auto& e : item->layout().elements)
                if (e.statement == statement && e.element == element) {
                    LadderCursor cursor{item->step(), item->index(), std::nullopt, std::nullopt,
                                        -1};
                    if (e.output >= 0) {
                        cursor.output = e.path;
                        cursor.outputIndex = e.output;
                    } else {
                        cursor.node = e.path;
                    }
                    setCursor(cursor);
                    return true;
                }
    return false;
}

void LadderPage::ensureCursorVisible() {
    const LadderCursor& cursor = m_drawing.cursor;
    NetworkItem* item = networkItem(cursor.step, cursor.network);
    if (!item)
        return;
    QRectF rect = item->boundingRect();
    if (const ladder::ElementLayout* element = cursorElement())
        rect = item->elementRect(*element);
    else if (cursor.node)
        rect = item->groupRect(*cursor.node);
    m_view->ensureVisible(item->mapRectToScene(rect), 20, 20);
}

NetworkItem* LadderPage::itemAt(const QPointF& scenePosition) const {
    for (const auto& step : m_items)
        for (NetworkItem* item : step)
            if (item->sceneBoundingRect().contains(scenePosition))
                return item;
    return nullptr;
}

LadderCursor LadderPage::cursorAt(const QPointF& scenePosition) const {
    NetworkItem* item = itemAt(scenePosition);
    if (!item)
        return {};
    LadderCursor cursor{item->step(), item->index(), std::nullopt, std::nullopt, -1};
    const int index = item->elementAt(item->mapFromScene(scenePosition));
    if (index < 0)
        return cursor;
    const ladder::ElementLayout& element = item->layout().elements[index];
    if (element.output >= 0) {
        cursor.output = element.path;
        cursor.outputIndex = element.output;
    } else {
        cursor.node = element.path;
    }
    return cursor;
}

void LadderPage::moveCursor(int key) {
    LadderCursor cursor = m_drawing.cursor;
    if (!cursor.valid()) {
        if (stepCount() > 0 && networkCount(0) > 0)
            setCursor({0, 0, std::nullopt, std::nullopt, -1});
        return;
    }
    NetworkItem* item = networkItem(cursor.step, cursor.network);
    const auto& elements = item->layout().elements;
    auto neighbourNetwork = [&](int direction) -> LadderCursor {
        int step = cursor.step;
        int network = cursor.network + direction;
        while (step >= 0 && step < stepCount() && (network < 0 || network >= networkCount(step))) {
            step += direction;
            if (step >= 0 && step < stepCount())
                network = direction > 0 ? 0 : networkCount(step) - 1;
        }
        if (step < 0 || step >= stepCount())
            return cursor;
        return {step, network, std::nullopt, std::nullopt, -1};
    };
    auto cursorOf = [&](const ladder::ElementLayout& element) {
        LadderCursor c{cursor.step, cursor.network, std::nullopt, std::nullopt, -1};
        if (element.output >= 0) {
            c.output = element.path;
            c.outputIndex = element.output;
        } else {
            c.node = element.path;
        }
        return c;
    };
    if (cursor.wholeNetwork()) {
        if ((key == Qt::Key_Down || key == Qt::Key_Right) && !item->collapsed() &&
            !elements.empty()) {
            setCursor(cursorOf(elements.front()));
            return;
        }
        if (key == Qt::Key_Down || key == Qt::Key_Up)
            setCursor(neighbourNetwork(key == Qt::Key_Down ? 1 : -1));
        return;
    }
    QRectF here;
    if (const ladder::ElementLayout* element = cursorElement())
        here = element->cell;
    else if (cursor.node)
        here = item->groupRect(*cursor.node).translated(-NetworkItem::kGutter, 0);
    const QPointF centre = here.center();
    const ladder::ElementLayout* best = nullptr;
    qreal bestScore = 0;
    for (const auto& element : elements) {
        const QPointF c = element.cell.center();
        const qreal dx = c.x() - centre.x();
        const qreal dy = c.y() - centre.y();
        qreal score = -1;
        switch (key) {
        case Qt::Key_Left:
            if (std::abs(dy) < here.height() / 2 && dx < -1)
                score = -dx;
            break;
        case Qt::Key_Right:
            if (std::abs(dy) < here.height() / 2 && dx > 1)
                score = dx;
            break;
        case Qt::Key_Up:
            if (dy < -1)
                score = -dy * 4 + std::abs(dx);
            break;
        case Qt::Key_Down:
            if (dy > 1)
                score = dy * 4 + std::abs(dx);
            break;
        default:
            break;
        }
        if (score >= 0 && (!best || score < bestScore)) {
            best = &element;
            bestScore = score;
        }
    }
    if (best)
        setCursor(cursorOf(*best));
    else if (key == Qt::Key_Up)
        setCursor({cursor.step, cursor.network, std::nullopt, std::nullopt, -1});
    else if (key == Qt::Key_Down)
        setCursor(neighbourNetwork(1));
}

std::vector<std::pair<int, int>> LadderPage::chosenNetworks() const {
    std::vector<std::pair<int, int>> chosen(m_drawing.marked.begin(), m_drawing.marked.end());
    const LadderCursor& cursor = m_drawing.cursor;
    if (chosen.empty() && cursor.valid())
        chosen.emplace_back(cursor.step, cursor.network);
    return chosen;
}

// ----- mouse and keys

void LadderPage::pressed(const QPointF& scenePosition, Qt::MouseButton button,
                         Qt::KeyboardModifiers modifiers) {
    NetworkItem* item = itemAt(scenePosition);
    if (item && button == Qt::LeftButton &&
        item->inCollapseBox(item->mapFromScene(scenePosition))) {
        toggleCollapsed(item->step(), item->index());
        return;
    }
    if (isLive()) {
        const LadderCursor at = cursorAt(scenePosition);
        m_drawing.cursor = at;
        const ladder::ElementLayout* element = cursorElement();
        if (button == Qt::LeftButton && element && !element->address.isEmpty())
            emit operandClicked(element->address);
        repaintItems();
        return;
    }
    if (item && button == Qt::LeftButton && item->option() &&
        item->optionBox().adjusted(-4, -4, 4, 4).contains(item->mapFromScene(scenePosition))) {
        setCursor({item->step(), item->index(), std::nullopt, std::nullopt, -1});
        toggleConfigOption(item->step(), item->index());
        return;
    }
    const LadderCursor at = cursorAt(scenePosition);
    if (button == Qt::LeftButton && (modifiers & Qt::ControlModifier) && at.valid()) {
        const auto key = std::make_pair(at.step, at.network);
        if (!m_drawing.marked.erase(key))
            m_drawing.marked.insert(key);
    } else if (button == Qt::LeftButton && (modifiers & Qt::ShiftModifier) && at.valid() &&
               m_drawing.cursor.valid() && at.step == m_drawing.cursor.step) {
        const auto [low, high] = std::minmax(at.network, m_drawing.cursor.network);
        for (int n = low; n <= high; ++n)
            m_drawing.marked.insert({at.step, n});
    } else if (button == Qt::LeftButton ||
               (button == Qt::RightButton && !m_drawing.marked.count({at.step, at.network}))) {
        m_drawing.marked.clear();
    }
    setCursor(at);
}

void LadderPage::doubleClicked(const QPointF& scenePosition) {
    if (isLive())
        return;
    for (std::size_t s = 0; s < m_headers.size(); ++s)
        if (m_headers[s]->isVisible() &&
            m_headers[s]->sceneBoundingRect().contains(scenePosition)) {
            editStepComment(static_cast<int>(s));
            return;
        }
    NetworkItem* item = itemAt(scenePosition);
    if (!item)
        return;
    const LadderCursor at = cursorAt(scenePosition);
    setCursor(at);
    if (item->option())
        editConfigOption(at.step, at.network);
    else if (at.wholeNetwork())
        editNetworkComment();
    else
        editProperties();
}

void LadderPage::showMenu(const QPointF& scenePosition, const QPoint& globalPosition) {
    if (isLive()) {
        const LadderCursor at = cursorAt(scenePosition);
        m_drawing.cursor = at;
        if (const ladder::ElementLayout* element = cursorElement();
            element && !element->address.isEmpty())
            emit operandMenuRequested(element->address, globalPosition);
        repaintItems();
        return;
    }
    QMenu menu(this);
    menu.setObjectName(QStringLiteral("ladderMenu"));
    QMenu* newNetwork = menu.addMenu(tr("&New Network"));
    newNetwork->addAction(tr("&Basic Network"), this, [this] { this->newNetwork(); });
    newNetwork->addAction(tr("&Config Option..."), this, [this] { newConfigOption(); });
    menu.addAction(tr("Cu&t Network(s)"), this, [this] { cutNetworks(); });
    menu.addAction(tr("&Copy Network(s)"), this, [this] { copyNetworks(); });
    menu.addAction(tr("&Paste Network(s)"), this, [this] { pasteNetworks(); });
    menu.addAction(tr("&Delete Network(s)"), this, [this] { deleteNetworks(); });
    menu.addSeparator();
    if (cursorElement()) {
        menu.addAction(tr("P&roperties..."), this, [this] { editProperties(); });
        menu.addAction(tr("Delete &Element"), this, [this] { deleteSelection(); });
    }
    menu.addAction(tr("Network Co&mment..."), this, [this] { editNetworkComment(); });
    menu.addAction(tr("&Edit Network"), this, [this] { enterEditMode(); });
    if (m_sequence > 0)
        menu.addAction(tr("New &Step"), this, [this] { newStep(); });
    menu.addAction(tr("New Se&quence..."), this, [this] { emit newSequenceRequested(); });
    menu.exec(globalPosition);
}

// While simulating, the keyboard does what the mouse does: Space is a click
// on the selected element, the Menu key or Shift+F10 its context menu.
bool LadderPage::handleLiveKey(int key, Qt::KeyboardModifiers modifiers) {
    const ladder::ElementLayout* element = cursorElement();
    NetworkItem* item = networkItem(m_drawing.cursor.step, m_drawing.cursor.network);
    if (!element || !item || element->address.isEmpty())
        return false;
    if (key == Qt::Key_Space && modifiers == Qt::NoModifier) {
        emit operandClicked(element->address);
        return true;
    }
    if (key == Qt::Key_Menu || (key == Qt::Key_F10 && modifiers == Qt::ShiftModifier)) {
        const QPointF centre = item->mapToScene(item->elementRect(*element).center());
        emit operandMenuRequested(element->address,
                                  m_view->viewport()->mapToGlobal(m_view->mapFromScene(centre)));
        return true;
    }
    return false;
}

bool LadderPage::handleKey(QKeyEvent* event) {
    const int key = event->key();
    const Qt::KeyboardModifiers modifiers = event->modifiers() & ~Qt::KeypadModifier;
    switch (key) {
    case Qt::Key_Left:
    case Qt::Key_Right:
    case Qt::Key_Down:
        moveCursor(key);
        return true;
    case Qt::Key_Up:
        if (modifiers & Qt::AltModifier) {
            LadderCursor cursor = m_drawing.cursor;
            if (cursor.node && !cursor.node->node.empty()) {
                cursor.node->node.pop_back();
                setCursor(cursor);
            }
            return true;
        }
        moveCursor(key);
        return true;
    case Qt::Key_Home:
        if (m_drawing.cursor.valid())
            setCursor(
                {m_drawing.cursor.step, m_drawing.cursor.network, std::nullopt, std::nullopt, -1});
        return true;
    default:
        break;
    }
    if (isLive())
        return handleLiveKey(key, modifiers);
    if (!m_document)
        return false;
    if (modifiers & (Qt::ControlModifier | Qt::AltModifier | Qt::MetaModifier))
        return false;
    switch (key) {
    case Qt::Key_Return:
    case Qt::Key_Enter:
        if (NetworkItem* item = networkItem(m_drawing.cursor.step, m_drawing.cursor.network);
            item && item->option())
            editConfigOption(item->step(), item->index());
        else
            editProperties();
        return true;
    case Qt::Key_Space:
        toggleConfigOption(m_drawing.cursor.step, m_drawing.cursor.network);
        return true;
    case Qt::Key_Delete:
    case Qt::Key_Backspace:
        deleteSelection();
        return true;
    case Qt::Key_Insert:
        newNetwork();
        return true;
    case Qt::Key_F2:
        undoNetwork();
        return true;
    case Qt::Key_F3:
        updateNetwork();
        return true;
    case Qt::Key_E:
        enterEditMode();
        return true;
    case Qt::Key_BracketLeft:
        setPlacement(Placement::Before);
        return true;
    case Qt::Key_BracketRight:
        setPlacement(Placement::After);
        return true;
    case Qt::Key_Backslash:
    case Qt::Key_Bar:
        setPlacement(Placement::Parallel);
        return true;
    default:
        break;
    }
    const QString text = event->text();
    const bool shift = modifiers & Qt::ShiftModifier;
    for (const ElementKindInfo& info : ladder::elementKinds()) {
        QString shortcut = QLatin1String(info.insertKey);
        const bool needsShift = shortcut.startsWith(QLatin1String("Shift+"));
        if (needsShift)
            shortcut = shortcut.mid(6);
        const QChar c = shortcut.front();
        const bool matches =
            c.isLetter() ? key == c.toUpper().unicode() && shift == needsShift : text == shortcut;
        if (matches) {
            insertElement(info.kind);
            return true;
        }
    }
    return false;
}

// ----- editing

bool LadderPage::editNetwork(const QString& name, int step, int network,
                             const std::function<ladder::EditResult(ladder::Network&)>& edit) {
    if (step < 0 || step >= stepCount() || network < 0 || network >= networkCount(step))
        return false;
    NetworkItem* item = networkItem(step, network);
    const std::vector<QString> before = signaturesOf(item->layout());
    ladder::StepLadder ladder = m_steps[step].ladder;
    const ladder::EditResult result = edit(ladder.networks[network]);
    if (!result.done()) {
        setMessage(tr("Not done: %1").arg(QString::fromStdString(result.refusal)));
        return false;
    }
    setMessage({});
    if (m_editSession && m_editSession->step == step && m_editSession->network == network) {
        m_steps[step].ladder = std::move(ladder);
        ladder::LayoutContext context;
        context.number = network + 1;
        context.title = tr("Network %1").arg(network + 1);
        context.firstStatement = m_steps[step].firstStatements[network];
        context.symbols = &m_symbols;
        item->setNetwork(m_steps[step].ladder.networks[network], context, m_namesVersion);
        placeItems();
    } else {
        commitStep(name, step, std::move(ladder));
    }
    selectAdded(step, network, before);
    return true;
}

void LadderPage::commitStep(const QString& name, int step, ladder::StepLadder ladder) {
    commitSteps(name, {{step, std::move(ladder)}});
}

void LadderPage::commitSteps(const QString& name,
                             std::vector<std::pair<int, ladder::StepLadder>> steps) {
    std::vector<std::pair<lang::StepAddress, ladder::StepLadder>> written;
    for (auto& [step, ladder] : steps) {
        if (m_pending && m_pending->first == step &&
            (m_pending->second >= static_cast<int>(ladder.networks.size()) ||
             !ladder.networks[m_pending->second].items.empty()))
            m_pending.reset();
        // A network without rungs is the page's until it holds one.
        std::erase_if(ladder.networks, [](const ladder::Network& n) { return n.items.empty(); });
        written.emplace_back(m_steps[step].address, std::move(ladder));
    }
    const int station = m_station;
    m_document->edit(name, [&](project::Project& p) {
        lang::UnitProgram& unit = project::programOf(p, station);
        for (const auto& [address, ladder] : written) {
            if (std::none_of(unit.steps.begin(), unit.steps.end(),
                             [&](const lang::Step& s) { return s.address == address; }))
                unit.steps.insert(unit.steps.begin(), lang::Step{address, std::nullopt, {}, {}});
            ladder::setStepLadder(unit, address, ladder);
        }
    });
}

void LadderPage::selectAdded(int step, int network, const std::vector<QString>& before) {
    NetworkItem* item = networkItem(step, network);
    if (!item)
        return;
    std::map<QString, int> counts;
    for (const QString& signature : before)
        ++counts[signature];
    for (const auto& element : item->layout().elements) {
        if (counts[signatureOf(element)]-- > 0)
            continue;
        LadderCursor cursor{step, network, std::nullopt, std::nullopt, -1};
        if (element.output >= 0) {
            cursor.output = element.path;
            cursor.outputIndex = element.output;
        } else {
            cursor.node = element.path;
        }
        setCursor(cursor);
        return;
    }
    LadderCursor cursor = m_drawing.cursor;
    cursor.step = step;
    cursor.network = network;
    if (!cursorElement() &&
        !(cursor.node && nodeAt(m_steps[step].ladder.networks[network], *cursor.node)))
        cursor = {step, network, std::nullopt, std::nullopt, -1};
    setCursor(cursor);
}

void LadderPage::insertElement(ElementKind kind) {
    if (!m_document || isLive())
        return;
    if (!m_drawing.cursor.valid()) {
        if (stepCount() == 0 || networkCount(0) == 0)
            newNetwork();
        else
            setCursor({0, networkCount(0) - 1, std::nullopt, std::nullopt, -1});
    }
    const LadderCursor cursor = m_drawing.cursor;
    if (!cursor.valid())
        return;
    const ladder::Network& network = m_steps[cursor.step].ladder.networks[cursor.network];
    const bool output = ladder::isOutput(kind);
    ElementFields fields;
    fields.kind = kind;
    if (kind == ElementKind::SequenceReset)
        fields.operand = QStringLiteral("S%1.1").arg(m_station).toStdString();
    if (kind == ElementKind::Jump)
        fields.operand = "+1";
    ElementDialog dialog(m_document, m_station, output, fields, this);
    if (dialog.exec() != QDialog::Accepted)
        return;
    const QString name = tr("Insert %1").arg(ElementKinds::name(kind));

    // The rung the insertion concerns: the selected one, or the network's last.
    std::optional<std::size_t> rungItem;
    if (cursor.node)
        rungItem = cursor.node->item;
    else if (cursor.output)
        rungItem = cursor.output->item;
    else
        for (std::size_t i = network.items.size(); i-- > 0;)
            if (std::holds_alternative<ladder::Rung>(network.items[i])) {
                rungItem = i;
                break;
            }

    if (output) {
        const ladder::Output made = *dialog.output();
        if (!rungItem || cursor.wholeNetwork()) {
            const std::size_t at = network.items.size();
            editNetwork(name, cursor.step, cursor.network, [&](ladder::Network& n) {
                return ladder::insertRung(n, at, ladder::Rung{std::nullopt, {made}});
            });
            return;
        }
        editNetwork(name, cursor.step, cursor.network,
                    [&](ladder::Network& n) { return ladder::addOutput(n, *rungItem, made); });
        return;
    }
    const ladder::Element made = *dialog.element();
    if (!rungItem) {
        setMessage(tr("A network starts with its output: insert a coil, latch, jump or "
                      "arithmetic box first, then its contacts."));
        return;
    }
    if (cursor.node) {
        const ladder::ElementPath at = *cursor.node;
        const Placement placement = m_placement;
        editNetwork(name, cursor.step, cursor.network, [&](ladder::Network& n) {
            switch (placement) {
            case Placement::Parallel:
                return ladder::insertInParallel(n, at, made);
            case Placement::Before:
                return ladder::insertInSeries(n, at, made, ladder::Side::Before);
            case Placement::After:
                break;
            }
            return ladder::insertInSeries(n, at, made, ladder::Side::After);
        });
        return;
    }
    // An output or the network: the element goes last in the rung's condition.
    const ladder::ElementPath root{*rungItem, {}};
    editNetwork(name, cursor.step, cursor.network, [&](ladder::Network& n) {
        return ladder::insertInSeries(n, root, made, ladder::Side::After);
    });
}

void LadderPage::editProperties() {
    if (!m_document || isLive())
        return;
    const LadderCursor cursor = m_drawing.cursor;
    if (!cursor.valid() || cursor.wholeNetwork())
        return;
    const ladder::Network& network = m_steps[cursor.step].ladder.networks[cursor.network];
    if (cursor.node) {
        const ladder::Circuit* node = nodeAt(network, *cursor.node);
        if (!node || !node->isElement())
            return;
        ElementDialog dialog(m_document, m_station, false, fieldsOf(node->element), this);
        if (dialog.exec() != QDialog::Accepted)
            return;
        const ladder::Element element = *dialog.element();
        const ladder::ElementPath at = *cursor.node;
        if (element == node->element)
            return;
        editNetwork(tr("Change Element"), cursor.step, cursor.network,
                    [&](ladder::Network& n) { return ladder::replaceElement(n, at, element); });
        setCursor(cursor);
        return;
    }
    const auto& rung = std::get<ladder::Rung>(network.items[cursor.output->item]);
    const ladder::Output& old = rung.outputs[static_cast<std::size_t>(cursor.outputIndex)];
    ElementDialog dialog(m_document, m_station, true, fieldsOf(old), this);
    if (dialog.exec() != QDialog::Accepted)
        return;
    ladder::Output output = *dialog.output();
    output.location = old.location;
    if (output == old)
        return;
    const std::size_t item = cursor.output->item;
    const auto index = static_cast<std::size_t>(cursor.outputIndex);
    editNetwork(tr("Change Output"), cursor.step, cursor.network,
                [&](ladder::Network& n) { return ladder::replaceOutput(n, item, index, output); });
    setCursor(cursor);
}

void LadderPage::deleteSelection() {
    if (!m_document || isLive())
        return;
    const LadderCursor cursor = m_drawing.cursor;
    if (!cursor.valid())
        return;
    if (cursor.wholeNetwork() || !m_drawing.marked.empty()) {
        deleteNetworks();
        return;
    }
    if (cursor.node) {
        const ladder::ElementPath at = *cursor.node;
        editNetwork(tr("Delete Element"), cursor.step, cursor.network,
                    [&](ladder::Network& n) { return ladder::removeNode(n, at); });
    } else {
        const std::size_t item = cursor.output->item;
        const auto index = static_cast<std::size_t>(cursor.outputIndex);
        editNetwork(tr("Delete Output"), cursor.step, cursor.network,
                    [&](ladder::Network& n) { return ladder::removeOutput(n, item, index); });
    }
    const ladder::ElementLayout* left = cursorElement();
    if (!left &&
        !(m_drawing.cursor.node && m_drawing.cursor.network < networkCount(m_drawing.cursor.step) &&
          nodeAt(m_steps[m_drawing.cursor.step].ladder.networks[m_drawing.cursor.network],
                 *m_drawing.cursor.node)))
        setCursor(cursor.network < networkCount(cursor.step)
                      ? LadderCursor{cursor.step, cursor.network, std::nullopt, std::nullopt, -1}
                      : LadderCursor{});
}

// ----- networks

void LadderPage::newNetwork() {
    if (!m_document || isLive())
        return;
    if (m_editSession)
        updateNetwork();
    if (stepCount() == 0) {
        setMessage(tr("This sequence has no step yet."));
        return;
    }
    const LadderCursor cursor = m_drawing.cursor;
    const int step = cursor.valid() ? cursor.step : stepCount() - 1;
    const int index = cursor.valid() ? cursor.network + 1 : networkCount(step);
    if (m_pending) {
        // Only one new network waits for its first rung; it moves here.
        m_pending.reset();
        rebuild();
    }
    m_pending = std::make_pair(step, std::min(index, networkCount(step)));
    rebuild();
    m_drawing.marked.clear();
    setCursor({m_pending->first, m_pending->second, std::nullopt, std::nullopt, -1});
    setMessage(tr("New network: insert its output first (L coil, S set, R reset, J jump ...)."));
}

void LadderPage::newConfigOption() {
    if (!m_document || isLive())
        return;
    if (m_sequence != 0 || stepCount() == 0) {
        setMessage(tr("Options stand at the start of the PLC code: open the PLC Code page."));
        return;
    }
    ladder::ConfigOption option;
    ConfigOptionDialog dialog(m_document, m_station, option, this);
    if (dialog.exec() != QDialog::Accepted)
        return;
    ladder::StepLadder ladder = m_steps[0].ladder;
    // After the options already there, before the rest of the code.
    int at = 0;
    while (at < static_cast<int>(ladder.networks.size()) &&
           ladder::configOptionOf(ladder.networks[at]))
        ++at;
    ladder.networks.insert(ladder.networks.begin() + at,
                           ladder::configOptionNetwork(*dialog.option()));
    if (m_pending && m_pending->first == 0 && m_pending->second >= at)
        ++m_pending->second;
    commitStep(tr("New Config Option"), 0, std::move(ladder));
    setCursor({0, at, std::nullopt, std::nullopt, -1});
}

void LadderPage::editConfigOption(int step, int network) {
    NetworkItem* item = networkItem(step, network);
    if (!m_document || isLive() || !item || !item->option())
        return;
    ConfigOptionDialog dialog(m_document, m_station, *item->option(), this);
    if (dialog.exec() != QDialog::Accepted || dialog.option() == item->option())
        return;
    const ladder::Network changed = ladder::configOptionNetwork(*dialog.option());
    editNetwork(tr("Change Config Option"), step, network, [&](ladder::Network& n) {
        n = changed;
        return ladder::EditResult{};
    });
    setCursor({step, network, std::nullopt, std::nullopt, -1});
}

void LadderPage::toggleConfigOption(int step, int network) {
    NetworkItem* item = networkItem(step, network);
    if (!m_document || isLive() || !item || !item->option())
        return;
    ladder::ConfigOption option = *item->option();
    option.checked = !option.checked;
    const ladder::Network changed = ladder::configOptionNetwork(option);
    editNetwork(option.checked ? tr("Enable Option") : tr("Disable Option"), step, network,
                [&](ladder::Network& n) {
                    n = changed;
                    return ladder::EditResult{};
                });
    setCursor({step, network, std::nullopt, std::nullopt, -1});
}

void LadderPage::copyNetworks() {
    std::vector<ladder::Network> networks;
    for (auto [step, network] : chosenNetworks())
        if (network < networkCount(step) && !m_steps[step].ladder.networks[network].items.empty())
            networks.push_back(m_steps[step].ladder.networks[network]);
    if (networks.empty())
        return;
    const QByteArray text = QByteArray::fromStdString(ladder::networksText(networks));
    auto* data = new QMimeData;
    data->setData(QLatin1String(kNetworksMimeType), text);
    data->setText(QString::fromUtf8(text));
    QApplication::clipboard()->setMimeData(data);
    setMessage(tr("%n network(s) copied.", nullptr, static_cast<int>(networks.size())));
}

void LadderPage::cutNetworks() {
    copyNetworks();
    deleteNetworks();
}

void LadderPage::pasteNetworks() {
    if (!m_document || isLive() || stepCount() == 0)
        return;
    const QMimeData* data = QApplication::clipboard()->mimeData();
    if (!data)
        return;
    const QByteArray text = data->hasFormat(QLatin1String(kNetworksMimeType))
                                ? data->data(QLatin1String(kNetworksMimeType))
                                : data->text().toUtf8();
    ladder::NetworksReading read = ladder::readNetworksText(text.toStdString());
    if (!read.error.empty() || read.networks.empty()) {
        setMessage(read.error.empty() ? tr("The clipboard holds no networks.")
                                      : tr("The clipboard holds no networks: %1")
                                            .arg(QString::fromStdString(read.error)));
        return;
    }
    const LadderCursor cursor = m_drawing.cursor;
    const int step = cursor.valid() ? cursor.step : stepCount() - 1;
    const int index = cursor.valid() ? cursor.network + 1 : networkCount(step);
    ladder::StepLadder ladder = m_steps[step].ladder;
    const auto count = static_cast<int>(read.networks.size());
    ladder.networks.insert(ladder.networks.begin() + index, read.networks.begin(),
                           read.networks.end());
    if (m_pending && m_pending->first == step && m_pending->second >= index)
        m_pending->second += count;
    commitStep(tr("Paste %n Network(s)", nullptr, count), step, std::move(ladder));
    m_drawing.marked.clear();
    for (int n = index; n < index + count && n < networkCount(step); ++n)
        m_drawing.marked.insert({step, n});
    setCursor({step, std::min(index, networkCount(step) - 1), std::nullopt, std::nullopt, -1});
}

void LadderPage::deleteNetworks() {
    if (!m_document || isLive())
        return;
    std::vector<std::pair<int, int>> chosen = chosenNetworks();
    if (chosen.empty())
        return;
    if (m_editSession)
        undoNetwork();
    std::sort(chosen.begin(), chosen.end());
    const int step = chosen.front().first;
    ladder::StepLadder ladder = m_steps[step].ladder;
    int removed = 0;
    for (auto it = chosen.rbegin(); it != chosen.rend(); ++it)
        if (it->first == step && it->second < static_cast<int>(ladder.networks.size())) {
            if (m_pending == *it)
                m_pending.reset();
            ladder.networks.erase(ladder.networks.begin() + it->second);
            ++removed;
        }
    m_drawing.marked.clear();
    const int first = chosen.front().second;
    commitStep(tr("Delete %n Network(s)", nullptr, removed), step, std::move(ladder));
    rebuild();
    if (networkCount(step) > 0)
        setCursor({step, std::min(first, networkCount(step) - 1), std::nullopt, std::nullopt, -1});
    else
        setCursor({});
}

void LadderPage::setAllCollapsed(bool collapsed) {
    for (auto& step : m_items)
        for (NetworkItem* item : step)
            item->setCollapsed(collapsed);
    placeItems();
    repaintItems();
}

void LadderPage::toggleCollapsed(int step, int network) {
    if (NetworkItem* item = networkItem(step, network)) {
        item->setCollapsed(!item->collapsed());
        placeItems();
        repaintItems();
    }
}

void LadderPage::editNetworkComment() {
    if (!m_document || isLive())
        return;
    const LadderCursor cursor = m_drawing.cursor;
    if (!cursor.valid())
        return;
    const ladder::Network& network = m_steps[cursor.step].ladder.networks[cursor.network];
    if (network.items.empty()) {
        setMessage(tr("Insert the network's output before its comment."));
        return;
    }
    bool ok = false;
    const QString comment = QInputDialog::getMultiLineText(
        this, tr("Network Comment"), tr("Comment of network %1:").arg(cursor.network + 1),
        QString::fromStdString(network.comment), &ok);
    if (!ok || comment.toStdString() == network.comment)
        return;
    editNetwork(tr("Comment Network %1").arg(cursor.network + 1), cursor.step, cursor.network,
                [&](ladder::Network& n) {
                    n.comment = comment.trimmed().toStdString();
                    return ladder::EditResult{};
                });
    setCursor({cursor.step, cursor.network, std::nullopt, std::nullopt, -1});
}

void LadderPage::editStepComment(int step) {
    if (!m_document || isLive() || step < 0 || step >= stepCount())
        return;
    const lang::StepAddress address = m_steps[step].address;
    const QString header = QString::fromStdString(lang::toString(address));
    bool ok = false;
    const QString comment =
        QInputDialog::getText(this, tr("Step Comment"), tr("Comment of step %1:").arg(header),
                              QLineEdit::Normal, m_stepComments[step], &ok)
            .trimmed();
    if (!ok || comment == m_stepComments[step])
        return;
    const int station = m_station;
    m_document->edit(tr("Comment Step %1").arg(header), [&](project::Project& p) {
        for (auto& s : project::programOf(p, station).steps)
            if (s.address == address)
                s.comment = comment.isEmpty()
                                ? std::nullopt
                                : std::optional<std::string>(" " + comment.toStdString());
    });
}

void LadderPage::newStep() {
    if (!m_document || isLive())
        return;
    int added = -1;
    std::string refusal;
    const int station = m_station;
    const int sequence = m_sequence;
    m_document->edit(tr("New Step of Sequence %1").arg(sequence), [&](project::Project& p) {
        const project::AddedStep step = project::addStep(p, station, sequence);
        added = step.step;
        refusal = step.refusal;
    });
    if (added < 0) {
        setMessage(QString::fromStdString(refusal));
        return;
    }
    for (int s = 0; s < stepCount(); ++s)
        if (m_steps[s].address.step == added) {
            // The new step gets a first network, waiting for its output.
            m_pending = std::make_pair(s, 0);
            rebuild();
            setCursor({s, 0, std::nullopt, std::nullopt, -1});
            setMessage(tr("Step %1 added: insert the output of its first network.").arg(added));
            return;
        }
}

// ----- edit mode

void LadderPage::enterEditMode() {
    if (!m_document || isLive() || !m_drawing.cursor.valid())
        return;
    if (m_editSession) {
        if (m_editSession->step == m_drawing.cursor.step &&
            m_editSession->network == m_drawing.cursor.network)
            return;
        updateNetwork();
    }
    m_editSession = EditSession{m_drawing.cursor.step, m_drawing.cursor.network};
    m_drawing.editingNetwork = std::make_pair(m_editSession->step, m_editSession->network);
    setMessage(tr("Network %1 is in edit mode: Update (F3) keeps its edits as one step, "
                  "Undo (F2) drops them.")
                   .arg(m_editSession->network + 1));
    updateActions();
    repaintItems();
}

void LadderPage::updateNetwork() {
    if (!m_editSession)
        return;
    const EditSession session = *m_editSession;
    m_editSession.reset();
    m_drawing.editingNetwork.reset();
    ladder::StepLadder ladder = m_steps[session.step].ladder;
    commitStep(tr("Edit Network %1").arg(session.network + 1), session.step, std::move(ladder));
    rebuild();
    setMessage(tr("Network %1 updated.").arg(session.network + 1));
    updateActions();
}

void LadderPage::undoNetwork() {
    if (!m_editSession)
        return;
    const EditSession session = *m_editSession;
    m_editSession.reset();
    m_drawing.editingNetwork.reset();
    rebuild();
    setMessage(tr("The edits of network %1 were dropped.").arg(session.network + 1));
    updateActions();
}

// ----- drag and drop

void LadderPage::startDrag(const QPointF& from) {
    if (isLive())
        return;
    const LadderCursor at = cursorAt(from);
    if (!at.node)
        return;
    setCursor(at);
    const QByteArray payload = QStringLiteral("%1 %2 %3 %4")
                                   .arg(reinterpret_cast<quintptr>(this))
                                   .arg(at.step)
                                   .arg(at.network)
                                   .arg(static_cast<qulonglong>(at.node->item))
                                   .toUtf8() +
                               [&] {
                                   QByteArray path;
                                   for (std::size_t i : at.node->node)
                                       path += ' ' + QByteArray::number(static_cast<qulonglong>(i));
                                   return path;
                               }();
    auto* data = new QMimeData;
    data->setData(QLatin1String(kElementMimeType), payload);
    auto* drag = new QDrag(m_view);
    drag->setMimeData(data);
    drag->exec(Qt::MoveAction);
}

void LadderPage::drop(const QPointF& scenePosition, const QByteArray& payload) {
    const QList<QByteArray> words = payload.split(' ');
    if (words.size() < 4 || words[0].toULongLong() != reinterpret_cast<quintptr>(this))
        return;
    const int step = words[1].toInt();
    const int network = words[2].toInt();
    ladder::ElementPath node{static_cast<std::size_t>(words[3].toULongLong()), {}};
    for (int i = 4; i < words.size(); ++i)
        node.node.push_back(static_cast<std::size_t>(words[i].toULongLong()));
    const LadderCursor target = cursorAt(scenePosition);
    if (!target.node)
        return;
    NetworkItem* item = networkItem(target.step, target.network);
    const int index = item->elementAt(item->mapFromScene(scenePosition));
    const ladder::Side side =
        index >= 0 && item->mapFromScene(scenePosition).x() <
                          item->elementRect(item->layout().elements[index]).center().x()
            ? ladder::Side::Before
            : ladder::Side::After;
    moveElement({step, network, node, std::nullopt, -1}, target, side);
}

bool LadderPage::moveElement(const LadderCursor& from, const LadderCursor& to, ladder::Side side) {
    auto exists = [this](const LadderCursor& c) {
        return c.node && c.step >= 0 && c.step < stepCount() && c.network >= 0 &&
               c.network < networkCount(c.step);
    };
    if (!m_document || isLive() || !exists(from) || !exists(to))
        return false;
    if (m_editSession)
        updateNetwork();
    const bool sameStep = from.step == to.step;
    ladder::StepLadder source = m_steps[from.step].ladder;
    ladder::StepLadder target = sameStep ? ladder::StepLadder{} : m_steps[to.step].ladder;
    ladder::StepLadder& into = sameStep ? source : target;
    const ladder::EditResult result = ladder::moveNode(source.networks[from.network], *from.node,
                                                       into.networks[to.network], *to.node, side);
    if (!result.done()) {
        setMessage(tr("Not moved: %1").arg(QString::fromStdString(result.refusal)));
        return false;
    }
    setMessage({});
    std::vector<std::pair<int, ladder::StepLadder>> steps;
    steps.emplace_back(from.step, std::move(source));
    if (!sameStep)
        steps.emplace_back(to.step, std::move(target));
    commitSteps(tr("Move Element"), std::move(steps));
    setCursor(
        {to.step, std::min(to.network, networkCount(to.step) - 1), std::nullopt, std::nullopt, -1});
    return true;
}

// ----- print and PDF

void LadderPage::paintPages(QPagedPaintDevice& device, const QString& title) const {
    QPainter painter(&device);
    const QRectF page(0, 0, device.width(), device.height());
    qreal width = 0;
    for (const auto& step : m_items)
        for (NetworkItem* item : step)
            width = std::max(width, item->layout().size.width());
    if (width <= 0)
        return;
    const qreal scale = std::min<qreal>(page.width() / width, device.logicalDpiX() / 96.0);
    render::LadderStyle style; // paper is white whatever the theme
    QFont titleFont = style.font(style.titlePixelSize + 2, true);
    qreal y = 0;
    painter.setFont(titleFont);
    painter.drawText(QRectF(0, 0, page.width(), 40 * scale), Qt::AlignLeft | Qt::AlignVCenter,
                     title);
    y = 48 * scale;
    for (std::size_t s = 0; s < m_items.size(); ++s) {
        if (m_sequence != 0) {
            if (y + 40 * scale > page.height()) {
                device.newPage();
                y = 0;
            }
            painter.setFont(titleFont);
            painter.drawText(QRectF(0, y, page.width(), 30 * scale),
                             Qt::AlignLeft | Qt::AlignVCenter,
                             QString::fromStdString(lang::toString(m_steps[s].address)));
            y += 34 * scale;
        }
        for (NetworkItem* item : m_items[s]) {
            const QSizeF size = item->layout().size * scale;
            if (y + size.height() > page.height() && y > 0) {
                device.newPage();
                y = 0;
            }
            painter.save();
            painter.translate(0, y);
            painter.scale(scale, scale);
            render::paintNetwork(painter, item->layout(), style);
            painter.restore();
            y += size.height() + kNetworkGap * scale;
        }
    }
}

bool LadderPage::exportPdf(const QString& path) {
    QString file = path;
    if (file.isEmpty()) {
        file = QFileDialog::getSaveFileName(this, tr("Export PDF"), QString(),
                                            tr("PDF documents (*.pdf)"));
        if (file.isEmpty())
            return false;
    }
    // Through a save file: a failed export leaves an older PDF as it was.
    QSaveFile out(file);
    QString error;
    if (out.open(QIODevice::WriteOnly)) {
        {
            QPdfWriter writer(&out);
            writer.setPageSize(QPageSize(QPageSize::A4));
            writer.setPageMargins(QMarginsF(15, 15, 15, 15), QPageLayout::Millimeter);
            writer.setResolution(150);
            writer.setTitle(pageTitle());
            paintPages(writer, writer.title());
        }
        error = project::commitSaveFile(out);
    } else {
        error = out.errorString();
    }
    if (!error.isEmpty()) {
        setMessage(tr("Could not export to %1.").arg(QDir::toNativeSeparators(file)));
        QMessageBox::warning(
            this, tr("Export PDF"),
            tr("Could not export to %1: %2").arg(QDir::toNativeSeparators(file), error));
        return false;
    }
    setMessage(tr("Exported to %1.").arg(file));
    return true;
}

void LadderPage::print() {
    QPrinter printer(QPrinter::HighResolution);
    QPrintDialog dialog(&printer, this);
    if (dialog.exec() != QDialog::Accepted)
        return;
    paintPages(printer, pageTitle());
}

} // namespace rs::ui
