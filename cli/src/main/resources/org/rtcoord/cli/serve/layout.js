// The live view's layout: every node placed by rule rather than by a force simulation, so that no two
// overlap, the same system is always drawn the same way (positions stay put between updates), and
// data flows left to right. Naming contexts are boxes around what they bind, nested as the contexts are.
'use strict';

const LAYOUT = {
  gap: 28,        // between neighbours, room for the connectors that run between them
  padding: 14,    // inside a context's box
  title: 22,      // above a context's box, where its name is drawn
  empty: { width: 90, height: 24 },
  // What splitting a column or wrapping a band costs, in pixels of the fit: after either, flows no
  // longer read left to right, so a small system keeps its columns whole.
  breakCost: 120,
};

/**
 * Each item's rank in the data flow: 0 for one nothing flows into, else one more than the highest
 * rank flowing into it. A cycle is broken at its first id, so that a loop of components still reads
 * left to right.
 */
function flowRanks(ids, flows) {
  const rank = new Map(ids.map(id => [id, 0]));
  const into = new Map(ids.map(id => [id, 0]));
  const onward = new Map();
  flows.forEach(([from, to]) => {
    if (from === to || !rank.has(from) || !rank.has(to)) return;
    if (!onward.has(from)) onward.set(from, []);
    onward.get(from).push(to);
    into.set(to, into.get(to) + 1);
  });
  const remaining = new Set(ids);
  const queue = ids.filter(id => into.get(id) === 0).sort();
  while (remaining.size) {
    if (!queue.length) queue.push([...remaining].sort()[0]);
    const next = queue.shift();
    if (!remaining.delete(next)) continue;
    (onward.get(next) || []).forEach(to => {
      if (!remaining.has(to)) return;
      rank.set(to, Math.max(rank.get(to), rank.get(next) + 1));
      into.set(to, into.get(to) - 1);
      if (into.get(to) === 0) queue.push(to);
    });
  }
  return rank;
}

/** Numbers from 1 to [most], sparse as they grow: the column heights and band widths worth trying. */
function candidates(most) {
  const tried = [];
  for (let n = 1; n < most; n = Math.max(n + 1, Math.round(n * 1.25))) tried.push(n);
  tried.push(Math.max(1, most));
  return tried;
}

/**
 * [boxes] ({ width, height, rank, key, place }) packed into columns by rank, each column split when
 * too tall, the columns wrapped into bands when too wide: of all the splits and wraps tried, the one
 * that fits a window [aspect] times as wide as it is high best, each split or wrap counted against it.
 * Returns the pack's size and how to place it.
 */
function pack(boxes, aspect) {
  const ordered = boxes.slice().sort((a, b) => a.rank - b.rank || (a.key < b.key ? -1 : a.key > b.key ? 1 : 0));
  const columns = [];
  ordered.forEach(box => {
    const last = columns[columns.length - 1];
    if (last && last[0].rank === box.rank) last.push(box); else columns.push([box]);
  });
  const tallest = Math.max(...columns.map(c => c.length));
  let best = null;
  candidates(tallest).forEach(height => {
    const chunks = columns.flatMap(column => {
      const split = [];
      for (let i = 0; i < column.length; i += height) split.push(column.slice(i, i + height));
      return split;
    }).map(items => ({
      items,
      width: Math.max(...items.map(i => i.width)),
      height: items.reduce((sum, i) => sum + i.height, 0) + LAYOUT.gap * (items.length - 1),
    }));
    candidates(chunks.length).forEach(across => {
      const bands = [];
      for (let i = 0; i < chunks.length; i += across) {
        const row = chunks.slice(i, i + across);
        bands.push({ chunks: row, width: row.reduce((s, c) => s + c.width, 0) + LAYOUT.gap * (row.length - 1),
          height: Math.max(...row.map(c => c.height)) });
      }
      const width = Math.max(...bands.map(b => b.width));
      const height = bands.reduce((s, b) => s + b.height, 0) + LAYOUT.gap * (bands.length - 1);
      const score = Math.max(width / aspect, height) + LAYOUT.breakCost * (chunks.length - columns.length + bands.length - 1);
      if (!best || score < best.score - 0.5 || (Math.abs(score - best.score) <= 0.5 && width * height < best.width * best.height)) {
        best = { score, width, height, bands };
      }
    });
  });
  return {
    width: best.width,
    height: best.height,
    rank: ordered.length ? ordered[0].rank : Infinity,
    place(x, y, positions) {
      let top = y;
      best.bands.forEach(band => {
        let left = x;
        band.chunks.forEach(chunk => {
          let below = top;
          chunk.items.forEach(item => {
            item.place(left + (chunk.width - item.width) / 2, below, positions);
            below += item.height + LAYOUT.gap;
          });
          left += chunk.width + LAYOUT.gap;
        });
        top += band.height + LAYOUT.gap;
      });
    },
  };
}

/**
 * The centre of each of [leaves] ({ id, parent, width, height, rank }), inside the boxes of the
 * [contexts] ({ id, parent }) that hold them, the whole shaped for a window [aspect] times as wide as
 * it is high: a map from id to { x, y }.
 */
function layoutSystem(leaves, contexts, aspect) {
  const below = new Map();
  const add = (parent, entry) => {
    if (!below.has(parent)) below.set(parent, []);
    below.get(parent).push(entry);
  };
  const known = new Set(contexts.map(c => c.id));
  contexts.forEach(c => add(known.has(c.parent) ? c.parent : '', { context: c.id }));
  leaves.forEach(leaf => add(known.has(leaf.parent) ? leaf.parent : '', { leaf }));
  const measure = entry => {
    if (entry.leaf) {
      const leaf = entry.leaf;
      return { width: leaf.width, height: leaf.height, rank: leaf.rank, key: leaf.id,
        place: (x, y, positions) => positions.set(leaf.id, { x: x + leaf.width / 2, y: y + leaf.height / 2 }) };
    }
    const inside = below.has(entry.context) ? pack(below.get(entry.context).map(measure), aspect)
      : { ...LAYOUT.empty, rank: Infinity, place() {} };
    return {
      width: Math.max(inside.width, LAYOUT.empty.width) + 2 * LAYOUT.padding,
      height: inside.height + 2 * LAYOUT.padding + LAYOUT.title,
      rank: inside.rank,
      key: entry.context,
      place: (x, y, positions) => inside.place(x + LAYOUT.padding, y + LAYOUT.title + LAYOUT.padding, positions),
    };
  };
  const positions = new Map();
  if (below.has('')) pack(below.get('').map(measure), aspect).place(0, 0, positions);
  return positions;
}
