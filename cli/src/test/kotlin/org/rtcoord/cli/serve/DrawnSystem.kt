package org.rtcoord.cli.serve

import kotlinx.serialization.json.Json
import kotlinx.serialization.json.jsonArray
import kotlinx.serialization.json.jsonObject
import kotlinx.serialization.json.jsonPrimitive
import org.rtcoord.RtcTree

/**
 * What the page in [browser] draws, read from its Cytoscape graph: each component's drawn state, and what is wrong with
 * the drawing: a connection or hosting without an edge, an edge without a rendered box, two node boxes that overlap, a
 * port off its component's edge.
 */
class DrawnSystem private constructor(val states: Map<String, String>, val problems: List<String>) {
    /** Reading a drawing, and the tree's states to compare it with. */
    companion object {
        /** Reads the drawing now. */
        fun of(browser: HeadlessChromium): DrawnSystem {
            val json = Json.parseToJsonElement(browser.evaluate(CHECK).jsonPrimitive.content).jsonObject
            return DrawnSystem(
                json["states"]!!.jsonObject.mapValues { it.value.jsonPrimitive.content },
                json["problems"]!!.jsonArray.map { it.jsonPrimitive.content },
            )
        }

        /**
         * What differs between the drawn states and those [tree]'s model holds now: a component drawn in another state,
         * or one the tree holds that is not drawn at any of its paths. Empty when they agree.
         */
        fun stateDifferences(drawn: DrawnSystem, tree: RtcTree): List<String> =
            tree.snapshot().components.mapNotNull { entry ->
                val path = entry.paths.map { it.toString() }.firstOrNull { it in drawn.states }
                when {
                    path == null -> "${entry.path} (${entry.overallState}) is not drawn"
                    drawn.states[path] != entry.overallState.name ->
                        "$path is drawn ${drawn.states[path]}, the tree holds ${entry.overallState}"
                    else -> null
                }
            } +
                drawn.states.keys
                    .filter { path ->
                        tree.snapshot().components.none { entry -> entry.paths.any { it.toString() == path } }
                    }
                    .map { "$it is drawn, but the tree holds no such component" }

        private val CHECK =
            """
            (() => {
              const cy = rtcoord.cy, network = rtcoord.network, problems = [];
              const box = b => '[' + [b.x1, b.y1, b.x2, b.y2].map(Math.round).join(', ') + ']';
              network.connections.forEach(c => {
                const key = c.source + ':' + c.sourcePort + '->' + c.target + ':' + c.targetPort;
                const edge = cy.edges().filter(e => e.data('connection') === key);
                if (edge.empty()) return problems.push('no edge for the connection ' + key);
                const b = edge.renderedBoundingBox();
                if (!(b.w > 0 && b.h > 0)) problems.push('the edge of ' + key + ' has the rendered box ' + box(b));
              });
              network.managers.forEach(m => m.hosts.forEach(h => {
                const edge = cy.getElementById('hosts:' + m.id + '->' + h);
                if (edge.empty()) return problems.push('no hosting edge from ' + m.id + ' to ' + h);
                const b = edge.renderedBoundingBox();
                if (!(b.w > 0 && b.h > 0)) problems.push('the hosting edge to ' + h + ' has the rendered box ' + box(b));
              }));
              // A node's body with its border, without what is drawn around it: its label, and the outline that marks a
              // logged error (Cytoscape 3.33's boundingBox counts an outline even with includeOutlines: false).
              const bodyOf = n => { const at = n.position(), w = n.outerWidth() / 2, h = n.outerHeight() / 2;
                return { x1: at.x - w, y1: at.y - h, x2: at.x + w, y2: at.y + h }; };
              const overlap = (a, b) => a.x1 < b.x2 && b.x1 < a.x2 && a.y1 < b.y2 && b.y1 < a.y2;
              const leaves = cy.nodes('.component, .manager, .external').map(n => [n.id(), bodyOf(n)]);
              for (let i = 0; i < leaves.length; i++) for (let j = i + 1; j < leaves.length; j++) {
                if (overlap(leaves[i][1], leaves[j][1])) problems.push(leaves[i][0] + ' ' + box(leaves[i][1]) + ' overlaps ' + leaves[j][0] + ' ' + box(leaves[j][1]));
              }
              const contexts = cy.nodes('.context');
              contexts.forEach((a, i) => contexts.forEach((b, j) => {
                if (j <= i || a.descendants().contains(b) || b.descendants().contains(a)) return;
                if (overlap(a.boundingBox({ includeLabels: false }), b.boundingBox({ includeLabels: false }))) problems.push('context ' + a.id() + ' overlaps ' + b.id());
              }));
              cy.nodes('.port').forEach(p => {
                const body = bodyOf(cy.getElementById(p.data('component')));
                const at = p.position();
                const near = (v, lo, hi) => v >= lo - 2 && v <= hi + 2;
                const onEdge = (near(at.x, body.x1, body.x1 + 2) || near(at.x, body.x2 - 2, body.x2) || near(at.y, body.y2 - 2, body.y2)) &&
                  near(at.x, body.x1, body.x2) && near(at.y, body.y1, body.y2);
                if (!onEdge) problems.push('port ' + p.id() + ' at ' + Math.round(at.x) + ',' + Math.round(at.y) + ' is off its component ' + box(body));
              });
              const states = {};
              cy.nodes('.component').filter(n => n.data('state') !== 'ZOMBIE').forEach(n => { states[n.id()] = n.data('state'); });
              return JSON.stringify({ problems, states });
            })()
            """
                .trimIndent()
    }
}
