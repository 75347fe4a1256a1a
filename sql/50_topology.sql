-- Topological maps (SPEC 7, seed 003 §II-A): per stored map, a graph of places (nodes
-- with positions) and typed edges, imported from the AMRL navigation graphs with
-- 'fleetmap topo import' (protocol/topo_store.h). Idempotent, like every file here.
--
-- A graph belongs to one map: deleting the map (map delete) deletes its graph through
-- the cascade. Replacing it (map import --replace) keeps the map's row and its graph,
-- unless '--drop topology' deletes it; a node the new map strands needs --force
-- (protocol/map_replace.h).
--
-- Nodes and edges carry their map's name as well as its id, so that the views below need
-- no join: in MariaDB 10.11 a SPATIAL INDEX search that follows any other read in the
-- same statement (the const lookup of the map by name, say) fails with error 1207
-- "Update locks cannot be acquired during a READ UNCOMMITTED transaction" (MDEV-26123).
-- Map names never change (a replaced map keeps its row, name and id).

CREATE TABLE IF NOT EXISTS topo_graphs (
  map_id      INT UNSIGNED NOT NULL PRIMARY KEY,
  source      VARCHAR(255) NOT NULL DEFAULT '',
  nodes       INT UNSIGNED NOT NULL,
  edges       INT UNSIGNED NOT NULL,
  imported_at TIMESTAMP(6) NOT NULL DEFAULT CURRENT_TIMESTAMP(6),
  CONSTRAINT fk_topo_graphs_map FOREIGN KEY (map_id) REFERENCES maps (id) ON DELETE CASCADE
) ENGINE=InnoDB;

CREATE TABLE IF NOT EXISTS topo_nodes (
  map_id      INT UNSIGNED NOT NULL,
  map         VARCHAR(64) NOT NULL,           -- maps.name (see above)
  node_id     INT UNSIGNED NOT NULL,          -- the file's id
  ord         INT UNSIGNED NOT NULL,          -- position in the file, keeps export order
  name        VARCHAR(255) NULL,              -- optional place name (NULL: none)
  x           DOUBLE NOT NULL,
  y           DOUBLE NOT NULL,
  pos         POINT REF_SYSTEM_ID=0 NOT NULL,
  PRIMARY KEY (map_id, node_id),
  UNIQUE KEY uq_topo_nodes_ord (map_id, ord),
  SPATIAL INDEX sx_topo_nodes_pos (pos),
  CONSTRAINT fk_topo_nodes_graph FOREIGN KEY (map_id) REFERENCES topo_graphs (map_id) ON DELETE CASCADE
) ENGINE=InnoDB;

CREATE TABLE IF NOT EXISTS topo_edges (
  map_id      INT UNSIGNED NOT NULL,
  map         VARCHAR(64) NOT NULL,           -- maps.name (see above)
  ord         INT UNSIGNED NOT NULL,          -- position in the file
  s0_id       INT UNSIGNED NOT NULL,
  s1_id       INT UNSIGNED NOT NULL,
  -- seed 003: corridor, room, door; stairs and elevator from the AMRL flags (common/planning/topo_graph.h)
  type        ENUM('corridor','room','door','stairs','elevator') NOT NULL,
  has_door    TINYINT(1) NOT NULL DEFAULT 0,
  has_automated_door TINYINT(1) NOT NULL DEFAULT 0,
  max_clearance DOUBLE NULL,                  -- metres of free half-width; NULL: no limit
  max_speed   DOUBLE NULL,                    -- m/s; NULL: no limit
  length      DOUBLE NOT NULL,                -- Euclidean, between the end nodes
  geom        LINESTRING REF_SYSTEM_ID=0 NOT NULL,
  PRIMARY KEY (map_id, ord),
  KEY ix_topo_edges_s1 (map_id, s1_id),
  SPATIAL INDEX sx_topo_edges_geom (geom),
  CONSTRAINT fk_topo_edges_s0 FOREIGN KEY (map_id, s0_id) REFERENCES topo_nodes (map_id, node_id) ON DELETE CASCADE,
  CONSTRAINT fk_topo_edges_s1 FOREIGN KEY (map_id, s1_id) REFERENCES topo_nodes (map_id, node_id) ON DELETE CASCADE,
  CONSTRAINT ck_topo_edges_ends CHECK (s0_id <> s1_id)
) ENGINE=InnoDB;

-- Databases created while this file had no name column (development builds of the
-- planning issue): add it and fill it in. No-ops otherwise.
ALTER TABLE topo_nodes ADD COLUMN IF NOT EXISTS map VARCHAR(64) NOT NULL AFTER map_id;
ALTER TABLE topo_edges ADD COLUMN IF NOT EXISTS map VARCHAR(64) NOT NULL AFTER map_id;
UPDATE topo_nodes n JOIN maps m ON m.id = n.map_id SET n.map = m.name WHERE n.map = '';
UPDATE topo_edges e JOIN maps m ON m.id = e.map_id SET e.map = m.name WHERE e.map = '';

-- For people with SQL and GIS tools (SPEC 4): nodes as points, edges as lines, by map name.
--   SELECT node_id, name FROM v_topo_nodes
--   WHERE map = 'campus' AND MBRContains(ST_GeomFromText('POLYGON((0 0,50 0,50 50,0 50,0 0))'), pos);
-- One table each, no join (see above), so the spatial index can answer.
CREATE OR REPLACE SQL SECURITY DEFINER VIEW v_topo_nodes AS
  SELECT map, map_id, node_id, name, x, y, pos
  FROM topo_nodes;

CREATE OR REPLACE SQL SECURITY DEFINER VIEW v_topo_edges AS
  SELECT map, map_id, ord AS edge, s0_id, s1_id, type, has_door, has_automated_door,
         max_clearance, max_speed, length, geom
  FROM topo_edges;

-- server: reads graphs (routes for robots). operator: imports and deletes them.
-- inspector: the views only.
GRANT SELECT ON topo_graphs TO fleetmap_server_role;
GRANT SELECT ON topo_nodes TO fleetmap_server_role;
GRANT SELECT ON topo_edges TO fleetmap_server_role;
GRANT SELECT, INSERT, DELETE ON topo_graphs TO fleetmap_operator_role;
GRANT SELECT, INSERT, DELETE ON topo_nodes TO fleetmap_operator_role;
GRANT SELECT, INSERT, DELETE ON topo_edges TO fleetmap_operator_role;
GRANT SELECT ON v_topo_nodes TO fleetmap_inspector_role;
GRANT SELECT ON v_topo_edges TO fleetmap_inspector_role;
