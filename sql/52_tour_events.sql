-- Guided tours (seed 003 §III, docs/topology-tour.md): what a guide told a robot on a
-- tour (the TourEvent op, docs/protocol.md), stamped with the robot's pose. The server
-- inserts them (robots only ever insert into rr); 'fleetmap topo tour build' reads one
-- robot's tour and stores the graph it builds in topo_* (50_topology.sql).
-- Idempotent, like every file here.

CREATE TABLE IF NOT EXISTS tour_events (
  id          BIGINT UNSIGNED NOT NULL AUTO_INCREMENT PRIMARY KEY,  -- the order events came in
  robot_id    INT UNSIGNED NOT NULL,
  map_id      INT UNSIGNED NULL,              -- the robot's map then (NULL: none assigned)
  tour        VARCHAR(255) NOT NULL DEFAULT '',  -- '' is the robot's default tour
  kind        ENUM('corridor','room','door','crossing','place') NOT NULL,
  name        VARCHAR(255) NULL,              -- a place's name (NULL: none)
  x           DOUBLE NOT NULL,
  y           DOUBLE NOT NULL,
  theta       DOUBLE NOT NULL,
  t           TIMESTAMP(6) NOT NULL,          -- the request's rr.created_at
  KEY ix_tour_events_robot_tour (robot_id, tour, id),
  CONSTRAINT fk_tour_events_robot FOREIGN KEY (robot_id) REFERENCES robots (id)
) ENGINE=InnoDB;

-- server: records the events. operator: builds graphs from them and clears old tours.
-- inspector: reads them.
GRANT SELECT, INSERT ON tour_events TO fleetmap_server_role;
GRANT SELECT, DELETE ON tour_events TO fleetmap_operator_role;
GRANT SELECT ON tour_events TO fleetmap_inspector_role;
