//! Why an impact could not be resolved.

/// An impact that could not be integrated, one variant per failure.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ImpactError {
    /// The contact points do not approach: the normal speed (m/s, positive approaching) is not
    /// positive, or not finite.
    NotApproaching {
        /// Normal relative speed of the contact points, m/s.
        normal_speed: f64,
    },
    /// The coefficient of restitution is negative or not finite.
    RestitutionOutOfRange {
        /// The coefficient given.
        e: f64,
    },
    /// The switches between friction modes did not end within the phase limit.
    TooManyPhases {
        /// The limit.
        limit: usize,
    },
    /// The normal impulse grew far past any the restitution could need.
    UnboundedImpulse,
    /// A phase stopped advancing with its zero-slip band already at its widest.
    DidNotConverge,
    /// The thesis's Euler scheme ([`super::Impact::euler`]) took all its steps without
    /// finishing the restitution.
    EulerDidNotFinish,
}

impl ImpactError {
    /// What failed, in words (the message without the leading "impact could not be
    /// resolved").
    pub fn reason(&self) -> String {
        match self {
            ImpactError::NotApproaching { normal_speed } => {
                format!("the bodies are not approaching (normal speed {normal_speed} m/s)")
            }
            ImpactError::RestitutionOutOfRange { e } => format!("restitution {e} out of range"),
            ImpactError::TooManyPhases { limit } => format!("more than {limit} phases"),
            ImpactError::UnboundedImpulse => "the impulse grew without bound".into(),
            ImpactError::DidNotConverge => "the integration did not converge".into(),
            ImpactError::EulerDidNotFinish => "the Euler scheme did not finish".into(),
        }
    }
}

impl std::fmt::Display for ImpactError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "impact could not be resolved: {}", self.reason())
    }
}

impl std::error::Error for ImpactError {}
