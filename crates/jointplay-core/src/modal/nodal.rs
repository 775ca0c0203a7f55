//! The coordinates of each node of a structure reduced to a modal body: a
//! frame structure (beam elements) has two translations and a section angle
//! per node, a plane solid (plane-stress or plane-strain elements) two
//! translations only.

/// The coordinates of each node, in this order within the node.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum NodalCoordinates {
    /// `(u_x, u_y, theta)` [m, m, rad]: frame (beam) elements.
    TranslationsAndRotation,
    /// `(u_x, u_y)` [m, m]: plane solid elements.
    Translations,
}

impl NodalCoordinates {
    /// The coordinates of `n_nodes` nodes in matrices of size `size`, when they are 3 or 2 per node.
    pub fn of_size(size: usize, n_nodes: usize) -> Option<Self> {
        match size.checked_div(n_nodes)? {
            3 if size == 3 * n_nodes => Some(Self::TranslationsAndRotation),
            2 if size == 2 * n_nodes => Some(Self::Translations),
            _ => None,
        }
    }

    /// Number of coordinates per node.
    pub fn per_node(self) -> usize {
        match self {
            Self::TranslationsAndRotation => 3,
            Self::Translations => 2,
        }
    }

    /// Whether coordinate `i` of the structure is a section angle.
    pub fn is_rotation(self, i: usize) -> bool {
        self == Self::TranslationsAndRotation && i % 3 == 2
    }
}
