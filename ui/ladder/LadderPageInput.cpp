// SPDX-License-Identifier: GPL-3.0-or-later
// What the states of a ladder page's tools do with the mouse and the keys:
// the page's side of IdleTool, DragTool and LiveTool.
#include "LadderPage.h"

#include "DragTool.h"
#include "LadderActions.h"
#include "LadderTool.h"
#include "LadderView.h"
#include "NetworkItem.h"
#include "StepHeaderItem.h"
#include "document/ProjectDocument.h"

#include <QDrag>
#include <QGraphicsRectItem>
#include <QGraphicsScene>
#include <QMenu>
#include <QMimeData>

#include <algorithm>

namespace rs::ui {

bool LadderPage::toggleCollapseAt(const QPointF& scenePosition) {
    NetworkItem* item = itemAt(scenePosition);
    if (!item || !item->inCollapseBox(item->mapFromScene(scenePosition)))
        return false;
    toggleCollapsed(item->step(), item->index());
    return true;
}

bool LadderPage::toggleOptionAt(const QPointF& scenePosition) {
    NetworkItem* item = itemAt(scenePosition);
    if (!item || !item->option() ||
        !item->optionBox().adjusted(-4, -4, 4, 4).contains(item->mapFromScene(scenePosition)))
        return false;
    setCursor({item->step(), item->index(), std::nullopt, std::nullopt, -1});
    toggleConfigOption(item->step(), item->index());
    return true;
}

void LadderPage::select(const QPointF& scenePosition, Qt::MouseButton button,
                        Qt::KeyboardModifiers modifiers) {
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

void LadderPage::openAt(const QPointF& scenePosition) {
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
    else if (item->network().block)
        editBlockPins(at.step, at.network);
    else if (at.wholeNetwork())
        editNetworkComment();
    else
        editProperties();
}

void LadderPage::openSelected() {
    if (NetworkItem* item = networkItem(m_drawing.cursor.step, m_drawing.cursor.network);
        item && item->option())
        editConfigOption(item->step(), item->index());
    else
        editProperties();
}

void LadderPage::showEditMenu(const QPoint& globalPosition) {
    const LadderActions& a = *m_actions;
    QMenu menu(this);
    menu.setObjectName(QStringLiteral("ladderMenu"));
    menu.addActions({a.newNetwork, a.insertBlock, a.newConfigOption, a.cutNetworks, a.copyNetworks,
                     a.pasteNetworks, a.deleteNetworks});
    menu.addSeparator();
    if (cursorElement())
        menu.addActions({a.properties, a.deleteSelection});
    if (blockStatus(m_drawing.cursor.step, m_drawing.cursor.network))
        menu.addActions({a.properties, a.updateBlock, a.blockDocumentation});
    menu.addActions({a.networkComment, a.editNetwork});
    if (m_sequence > 0)
        menu.addAction(a.newStep);
    menu.addAction(a.newSequence);
    menu.exec(globalPosition);
}

// ----- drag and drop

void LadderPage::dragFrom(const QPointF& from, LadderTool& resume) {
    const LadderCursor at = cursorAt(from);
    if (!at.node)
        return;
    setCursor(at);
    m_dragTool->run(from, resume);
}

namespace {

// Where a dragged element comes from: the page it belongs to and its place.
struct DragSource {
    quintptr page = 0;
    int step = 0;
    int network = 0;
    ladder::ElementPath node;
};

std::optional<DragSource> readDragSource(const QByteArray& payload) {
    const QList<QByteArray> words = payload.split(' ');
    if (words.size() < 4)
        return std::nullopt;
    DragSource source{static_cast<quintptr>(words[0].toULongLong()), words[1].toInt(),
                      words[2].toInt(), ladder::ElementPath{}};
    source.node.item = static_cast<std::size_t>(words[3].toULongLong());
    for (int i = 4; i < words.size(); ++i)
        source.node.node.push_back(static_cast<std::size_t>(words[i].toULongLong()));
    return source;
}

constexpr qreal kDropPlaceWidth = 4;

} // namespace

QMimeData* LadderPage::elementDragData(const QPointF& from) const {
    const LadderCursor at = cursorAt(from);
    if (!at.node)
        return nullptr;
    QByteArray payload = QStringLiteral("%1 %2 %3 %4")
                             .arg(reinterpret_cast<quintptr>(this))
                             .arg(at.step)
                             .arg(at.network)
                             .arg(static_cast<qulonglong>(at.node->item))
                             .toUtf8();
    for (std::size_t i : at.node->node)
        payload += ' ' + QByteArray::number(static_cast<qulonglong>(i));
    auto* data = new QMimeData;
    data->setData(QLatin1String(kElementMimeType), payload);
    return data;
}

void LadderPage::dragElement(const QPointF& from) {
    QMimeData* data = elementDragData(from);
    if (!data)
        return;
    auto* drag = new QDrag(m_view);
    drag->setMimeData(data);
    drag->exec(Qt::CopyAction | Qt::MoveAction, Qt::CopyAction);
    hideDropPlace();
}

std::optional<LadderPage::DropPlace> LadderPage::dropPlaceAt(const QPointF& scenePosition,
                                                             const QByteArray& payload) const {
    const std::optional<DragSource> source = readDragSource(payload);
    if (!source || source->page != reinterpret_cast<quintptr>(this) || !m_tool->edits() ||
        !editable())
        return std::nullopt;
    const LadderCursor target = cursorAt(scenePosition);
    if (!target.node)
        return std::nullopt;
    NetworkItem* item = networkItem(target.step, target.network);
    const QPointF local = item->mapFromScene(scenePosition);
    const int index = item->elementAt(local);
    const QRectF element =
        index >= 0 ? item->elementRect(item->layout().elements[index]) : QRectF();
    const ladder::Side side =
        index >= 0 && local.x() < element.center().x() ? ladder::Side::Before : ladder::Side::After;
    const qreal x = side == ladder::Side::Before ? element.left() : element.right();
    const QRectF mark = index >= 0 ? QRectF(x - kDropPlaceWidth / 2, element.top(), kDropPlaceWidth,
                                            element.height())
                                   : QRectF();
    return DropPlace{{source->step, source->network, source->node, std::nullopt, -1},
                     target,
                     side,
                     item->mapRectToScene(mark)};
}

void LadderPage::showDropPlace(const QPointF& scenePosition, const QByteArray& payload, bool move) {
    const std::optional<DropPlace> place = dropPlaceAt(scenePosition, payload);
    if (!place) {
        hideDropPlace();
        return;
    }
    if (!m_dropPlace) {
        m_dropPlace = m_scene->addRect(QRectF(), Qt::NoPen);
        m_dropPlace->setZValue(1000); // above every network
    }
    m_dropPlace->setBrush(palette().color(QPalette::Highlight));
    m_dropPlace->setRect(place->mark);
    m_dropPlace->setVisible(!place->mark.isEmpty());
    setMessage(move ? tr("Moving: drop it before or after an element. Release Shift to copy.")
                    : tr("Copying: drop it before or after an element. Hold Shift to move."));
}

void LadderPage::hideDropPlace() {
    if (m_dropPlace && m_dropPlace->isVisible()) {
        m_dropPlace->hide();
        setMessage({});
    }
}

bool LadderPage::isDropPlaceShown() const {
    return m_dropPlace && m_dropPlace->isVisible();
}

void LadderPage::dropElement(const QPointF& scenePosition, const QByteArray& payload, bool move) {
    hideDropPlace();
    const std::optional<DropPlace> place = dropPlaceAt(scenePosition, payload);
    if (!place)
        return;
    if (move)
        moveElement(place->from, place->to, place->side);
    else
        copyElement(place->from, place->to, place->side);
}

// ----- live

void LadderPage::pointAt(const QPointF& scenePosition) {
    m_drawing.cursor = cursorAt(scenePosition);
    explainOutput();
    repaintItems();
}

void LadderPage::reportOperand() {
    if (const ladder::ElementLayout* element = cursorElement();
        element && !element->address.isEmpty())
        emit operandClicked(element->address);
}

void LadderPage::reportOperandMenu(std::optional<QPoint> globalPosition) {
    const ladder::ElementLayout* element = cursorElement();
    if (!element || element->address.isEmpty())
        return;
    if (!globalPosition) {
        NetworkItem* item = networkItem(m_drawing.cursor.step, m_drawing.cursor.network);
        const QPointF centre = item->mapToScene(item->elementRect(*element).center());
        globalPosition = m_view->viewport()->mapToGlobal(m_view->mapFromScene(centre));
    }
    emit operandMenuRequested(element->address, *globalPosition);
}

} // namespace rs::ui
